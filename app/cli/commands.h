#pragma once

#include "clisession.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QStringList>

namespace db::cli {

struct Context
{
    const ProtocolRegistry &registry;
    Options options;
    QStringList args; // positional arguments after the command name
    QTextStream &out;
    QTextStream &err;
    QString type; // --type for objects the description does not know
    QString file = {}; // --file: read/write the value as raw bytes from/to this file
    QString output = {}; // -o/--output (dcf)
    bool all = false; // --all (nmt: broadcast)
    // Every parsed option, for command-specific ones (Command::options): parser->value("vel").
    const QCommandLineParser *parser = nullptr;
};

struct Command
{
    const char *name;
    const char *synopsis;
    const char *summary;
    int minArgs;
    int maxArgs;
    int (*run)(Context &context);
    // Options only this command (family) takes, added to the parser by main.cpp. Several
    // commands may name the same option; it is added once.
    QList<QCommandLineOption> (*options)() = nullptr;
};

const QList<Command> &commands();

// Prints "drivebench-cli: <cause>" on stderr and returns the matching exit code.
int fail(Context &context, const Error &error);

} // namespace db::cli
