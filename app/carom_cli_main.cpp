#include "cli.h"

#include <QCoreApplication>

#include <cstdio>

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setApplicationName("carom-cli");
  QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION));
  QTextStream out(stdout);
  QTextStream err(stderr);
  return carom::cli::runCli(QCoreApplication::arguments().mid(1), out, err);
}
