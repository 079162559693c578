#include "app/cli/cli.h"
#include "sim/io/file_names.h"

#include <QCoreApplication>

#include <cstdio>

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setApplicationName("carom-cli");
  QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION));
  QTextStream out(stdout);
  QTextStream err(stderr);
  // Not QCoreApplication::arguments(): it would turn a file name's bytes that are not UTF-8
  // into U+FFFD, and then name another file.
  QStringList arguments;
  for (int i = 1; i < argc; ++i) arguments << carom::io::decodeFileName(argv[i]);
  const int code = carom::cli::runCli(arguments, out, err);
  out.flush();
  // A report that could not be written (a full disk, a closed pipe) is a failure, not a success.
  if (out.status() != QTextStream::Ok || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    err << "carom-cli: cannot write the output\n";
    return carom::cli::kInternalError;
  }
  return code;
}
