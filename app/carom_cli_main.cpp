#include "app/cli/cli.h"

#include <QCoreApplication>

#include <cstdio>

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setApplicationName("carom-cli");
  QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION));
  QTextStream out(stdout);
  QTextStream err(stderr);
  const int code = carom::cli::runCli(QCoreApplication::arguments().mid(1), out, err);
  out.flush();
  // A report that could not be written (a full disk, a closed pipe) is a failure, not a success.
  if (out.status() != QTextStream::Ok || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    err << "carom-cli: cannot write the output\n";
    return carom::cli::kInternalError;
  }
  return code;
}
