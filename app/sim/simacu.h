#pragma once

#include <QCommandLineParser>
#include <QTextStream>

namespace db::app {

// `drivebench-sim acu`: its options, and the runner (serves until SIGINT/SIGTERM via the event
// loop). Returns the process exit code: 2 for bad options, 3 when the port cannot be served.
void addAcuOptions(QCommandLineParser &parser);
int runAcu(const QCommandLineParser &parser, QTextStream &out, QTextStream &err);

} // namespace db::app
