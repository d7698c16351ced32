#pragma once

#include <QCommandLineParser>
#include <QTextStream>

#include <functional>

namespace db::app {

class AcuConsole;

// `drivebench-sim acu`: its options, and the runner (serves until SIGINT/SIGTERM via the event
// loop). Returns the process exit code: 2 for bad options, 3 when the port cannot be served.
// With readLines (--control), a control console on the simulator is handed to it once the port
// listens.
void addAcuOptions(QCommandLineParser &parser);
int runAcu(const QCommandLineParser &parser, QTextStream &out, QTextStream &err,
           const std::function<void(AcuConsole *)> &readLines = {});

} // namespace db::app
