// drivebench-cli: headless access to drives for scripts (README "CLI").
#include "../common/protocols.h"
#include "commands.h"
#include "core/printable.h"
#include "terminaldevice.h"
#include "translations/language.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QRegularExpression>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

using namespace db;

namespace {

QtMessageHandler g_defaultHandler = nullptr;

// --verbose logs the libraries' lines, which quote raw traffic: escaped like everything else.
void printableMessages(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    g_defaultHandler(type, context, printable(message));
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("drivebench-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEBENCH_VERSION));
    // Before anything is worded: the help texts are translated too.
    const QString langArgument = i18n::languageArgument(QCoreApplication::arguments());
    i18n::installTranslations(app, i18n::chooseLanguage(langArgument));
    // Every line a command prints goes through TerminalDevice: no control character from a
    // device or a file reaches the terminal raw, whichever print site it takes.
    cli::TerminalDevice outDevice(stdout);
    cli::TerminalDevice errDevice(stderr);
    QTextStream out(&outDevice);
    QTextStream err(&errDevice);
    g_defaultHandler = qInstallMessageHandler(printableMessages);

    QString description = QCoreApplication::translate(
        "cli", "drivebench command line: read and write drive objects from scripts.\n\nCommands:");
    for (const cli::Command &c : cli::commands())
        description += QStringLiteral("\n  %1 %2\n      %3")
                           .arg(QLatin1String(c.name), QLatin1String(c.synopsis),
                                QCoreApplication::translate("cli", c.summary));
    description += QCoreApplication::translate(
        "cli",
        "\n\nExit codes: 0 ok, 1 failure, 2 usage, 3 connection, 4 timeout, 5 malformed "
        "answer, 6 device error, 128 + N stopped by signal N (record: 130 Ctrl-C, 143 "
        "SIGTERM).");

    QCommandLineParser parser;
    parser.setApplicationDescription(description);
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption timeout(
        { QStringLiteral("t"), QStringLiteral("timeout") },
        QCoreApplication::translate("cli", "Time limit per request in ms (default 1000)."),
        QStringLiteral("ms"), QStringLiteral("1000"));
    const QCommandLineOption connectTimeout(
        QStringLiteral("connect-timeout"),
        QCoreApplication::translate("cli", "Time limit for connecting in ms (default 3000)."),
        QStringLiteral("ms"), QStringLiteral("3000"));
    const QCommandLineOption hex(QStringLiteral("hex"),
                                 QCoreApplication::translate("cli", "Print integers in hex."));
    const QCommandLineOption type(
        QStringLiteral("type"),
        QCoreApplication::translate("cli",
                                    "Data type of an object the device description does "
                                    "not know (u8, i16, u32, REAL32, ...)."),
        QStringLiteral("type"));
    const QCommandLineOption verbose(
        QStringLiteral("verbose"),
        QCoreApplication::translate("cli", "Name what is printed and log the traffic on stderr."));
    const QCommandLineOption file(
        QStringLiteral("file"),
        QCoreApplication::translate("cli", "read/write: the value as raw bytes to/from this file."),
        QStringLiteral("file"));
    const QCommandLineOption output({ QStringLiteral("o"), QStringLiteral("output") },
                                    QCoreApplication::translate("cli", "dcf: the file to write."),
                                    QStringLiteral("file"));
    const QCommandLineOption sdo(
        QStringLiteral("sdo"),
        QCoreApplication::translate("cli",
                                    "CANopen SDO mode: auto (default), expedited, segmented, "
                                    "block."),
        QStringLiteral("mode"));
    const QCommandLineOption ram(
        QStringLiteral("ram"),
        QCoreApplication::translate("cli",
                                    "VABus: write the RAM copy of the data set (data set + 5), "
                                    "sparing the inverter's EEPROM; lost at power-off."));
    const QCommandLineOption all(
        QStringLiteral("all"), QCoreApplication::translate("cli", "nmt: every node (broadcast)."));
    const QCommandLineOption lang(
        QStringLiteral("lang"),
        QCoreApplication::translate("cli",
                                    "Language of the messages: de or en (default: "
                                    "DRIVEBENCH_LANG, else LC_ALL, LC_MESSAGES, LANG)."),
        QStringLiteral("language"));
    const QList<QCommandLineOption> common { timeout, connectTimeout, hex, type, verbose,
                                             file,    output,         sdo, ram,  all,
                                             lang };
    parser.addOptions(common);
    QStringList taken; // option names in use; each command family may add its own
    for (const QCommandLineOption &o : common)
        taken += o.names();
    for (const cli::Command &c : cli::commands()) {
        if (!c.options)
            continue;
        for (const QCommandLineOption &o : c.options()) {
            bool fresh = true;
            for (const QString &n : o.names())
                fresh = fresh && !taken.contains(n);
            if (fresh && parser.addOption(o))
                taken += o.names();
        }
    }
    parser.addPositionalArgument(QStringLiteral("command"),
                                 QCoreApplication::translate("cli", "What to do (see above)."));
    // "-100" would be read as the options -1, -0, -0: a negative number that is not the value of
    // the option before it is a positional argument (setpoint 3 -100), so it reaches the parser
    // with a marker instead of its minus sign and gets the sign back afterwards. None of our
    // options is a digit.
    constexpr QChar kMinusMarker(0x2212); // MINUS SIGN, restored to '-'
    static const QRegularExpression negativeNumber(QStringLiteral("^-\\.?[0-9]"));
    QStringList valueOptions;
    for (const QCommandLineOption &o : common)
        if (!o.valueName().isEmpty())
            for (const QString &n : o.names())
                valueOptions += (n.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + n;
    for (const cli::Command &c : cli::commands()) {
        if (!c.options)
            continue;
        for (const QCommandLineOption &o : c.options())
            if (!o.valueName().isEmpty())
                for (const QString &n : o.names())
                    valueOptions +=
                        (n.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + n;
    }
    QStringList arguments = app.arguments();
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        if (arguments.at(i) == QLatin1String("--"))
            break;
        if (negativeNumber.match(arguments.at(i)).hasMatch()
            && !valueOptions.contains(arguments.at(i - 1)))
            arguments[i][0] = kMinusMarker;
    }
    parser.process(arguments);
    if (parser.isSet(lang) && !i18n::languages().contains(parser.value(lang))) {
        err << QCoreApplication::translate("cli", "drivebench-cli: --lang takes one of: %1")
                   .arg(i18n::languages().join(QStringLiteral(", ")))
            << Qt::endl;
        return cli::ExitUsage;
    }

    QStringList args = parser.positionalArguments();
    for (QString &a : args)
        if (a.startsWith(kMinusMarker))
            a[0] = QLatin1Char('-');
    if (args.isEmpty()) {
        err << Tr::tr("drivebench-cli: no command given; try drivebench-cli --help") << Qt::endl;
        return cli::ExitUsage;
    }
    const QString name = args.takeFirst();
    const cli::Command *command = nullptr;
    for (const cli::Command &c : cli::commands()) {
        if (name == QLatin1String(c.name))
            command = &c;
    }
    if (!command) {
        err << Tr::tr("drivebench-cli: unknown command '%1'; try drivebench-cli --help").arg(name)
            << Qt::endl;
        return cli::ExitUsage;
    }
    if (args.size() < command->minArgs || args.size() > command->maxArgs) {
        err << Tr::tr("drivebench-cli: usage: drivebench-cli %1 %2")
                   .arg(QLatin1String(command->name), QLatin1String(command->synopsis))
            << Qt::endl;
        return cli::ExitUsage;
    }
    bool ok1 = false;
    bool ok2 = false;
    cli::Options options;
    options.requestTimeoutMs = parser.value(timeout).toInt(&ok1);
    options.connectTimeoutMs = parser.value(connectTimeout).toInt(&ok2);
    if (!ok1 || !ok2 || options.requestTimeoutMs <= 0 || options.connectTimeoutMs <= 0) {
        err << Tr::tr("drivebench-cli: --timeout and --connect-timeout take a positive number "
                      "of ms")
            << Qt::endl;
        return cli::ExitUsage;
    }
    options.hex = parser.isSet(hex);
    options.verbose = parser.isSet(verbose);
    options.sdoMode = parser.value(sdo);
    options.ram = parser.isSet(ram);
    // Errors reach the user as one line from the command itself; the libraries' log lines only
    // with --verbose (QT_LOGGING_RULES still overrides this).
    QLoggingCategory::setFilterRules(options.verbose ? QStringLiteral("drivebench.*.debug=false")
                                                     : QStringLiteral("drivebench.*=false"));
    cli::Context context { app::protocolRegistry(), options, args, out, err, parser.value(type) };
    context.file = parser.value(file);
    context.output = parser.value(output);
    context.all = parser.isSet(all);
    context.parser = &parser;
    return command->run(context);
}
