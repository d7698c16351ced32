#include "commands_params.h"

#include "core/parameterrunner.h"
#include "core/printable.h"

#include <QEventLoop>
#include <QFileInfo>

namespace db::cli {

namespace {

const QString kOnly = QStringLiteral("only");
const QString kStore = QStringLiteral("store");
const QString kNoVerify = QStringLiteral("no-verify");

Error usage(const QString &message)
{
    return Error(Error::Kind::InvalidArgument, message);
}

// A parameter-set file that cannot be read or written: the message already names the file and
// line ("set.dbp:7: ..."), so no "malformed answer" kind in front of it.
int failFile(Context &c, const Error &error)
{
    c.err << "drivebench-cli: " << error.message() << Qt::endl;
    return exitCodeFor(error);
}

// Opens uri in session and runs a backup to its end in a local event loop (the CLI is
// synchronous by design). A device without a description has nothing to back up: usage error.
Result<ParameterSet> backupFrom(Context &c, Session &session, const QString &uri,
                                ParameterBackup::Scope scope)
{
    if (auto opened = session.open(uri); !opened)
        return opened.error();
    DeviceConnection *connection = session.connection();
    if (connection->dictionary().isEmpty())
        return usage(QStringLiteral("no device description for %1: give ?eds=FILE")
                         .arg(connection->uri().toString()));
    ParameterBackup backup(connection);
    backup.setScope(scope);
    QEventLoop loop;
    QObject::connect(&backup, &ParameterBackup::finished, &loop, &QEventLoop::quit);
    if (c.options.verbose) {
        QObject::connect(&backup, &ParameterBackup::progress, &loop, [&c](int done, int total) {
            if (done == total || done % 25 == 0)
                c.err << "read " << done << "/" << total << Qt::endl;
        });
    }
    backup.start();
    loop.exec();
    for (const QString &warning : backup.warnings())
        c.err << "warning: " << printable(warning) << Qt::endl;
    return backup.result();
}

// A diff side is a URI when it names a scheme ("refgo://..."); anything else is a file.
bool isUri(const QString &text)
{
    return text.contains(QLatin1String("://"));
}

} // namespace

QList<QCommandLineOption> paramsOptions()
{
    return {
        QCommandLineOption(kOnly,
                           QStringLiteral("restore: only these objects, e.g. 6083:0,6084:0."),
                           QStringLiteral("INDEX:SUB,...")),
        QCommandLineOption(kStore,
                           QStringLiteral("restore: store to non-volatile memory afterwards "
                                          "(1010h sub 1 = \"save\") when every row verified.")),
        QCommandLineOption(kNoVerify, QStringLiteral("restore: do not read each object back.")),
    };
}

int backup(Context &c)
{
    if (c.output.isEmpty())
        return fail(c, usage(QStringLiteral("backup needs the output file: -o FILE")));
    Session session(c.registry, c.options);
    const auto set = backupFrom(c, session, c.args.at(0), ParameterBackup::Scope::Storable);
    if (!set)
        return fail(c, set.error());
    if (auto saved = set->save(c.output); !saved)
        return failFile(c, saved.error());
    c.out << "backed up " << set->size() << " objects from " << printable(set->source) << " to "
          << printable(c.output) << Qt::endl;
    return ExitOk;
}

int restore(Context &c)
{
    // The file first: a corrupt or foreign file must be refused before anything is connected.
    const auto set = ParameterSet::load(c.args.at(1));
    if (!set)
        return failFile(c, set.error());
    QList<ObjectAddress> only;
    if (c.parser && c.parser->isSet(kOnly)) {
        for (const QString &part : c.parser->value(kOnly).split(u',', Qt::SkipEmptyParts)) {
            const auto address = ObjectAddress::parse(part.trimmed());
            if (!address)
                return fail(c, usage(QStringLiteral("--only: %1").arg(address.error().message())));
            if (!set->contains(*address))
                return fail(c,
                            usage(QStringLiteral("--only: %1 is not in %2")
                                      .arg(address->toString(), c.args.at(1))));
            only.append(*address);
        }
        if (only.isEmpty())
            return fail(c, usage(QStringLiteral("--only needs INDEX:SUB,...")));
    }
    Session session(c.registry, c.options);
    if (auto opened = session.open(c.args.at(0)); !opened)
        return fail(c, opened.error());
    const DeviceIdentity &device = session.connection()->dictionary().identity;
    if (!set->identity.productName.isEmpty() && !device.productName.isEmpty()
        && set->identity.productName != device.productName)
        return fail(c,
                    usage(QStringLiteral("%1 is a set for '%2', but %3 is a '%4'")
                              .arg(c.args.at(1), set->identity.productName, c.args.at(0),
                                   device.productName)));
    // The product code the device reports (1018h.2) must match the set's, when both are known.
    if (set->identity.productCode != 0
        && session.connection()->dictionary().contains(ObjectAddress(0x1018, 2))) {
        const auto code = session.read({ 0x1018, 2 });
        if (code && code->toULongLong() != set->identity.productCode)
            return fail(c,
                        usage(QStringLiteral("%1 is a set for product code 0x%2, but the "
                                             "device reports 0x%3")
                                  .arg(c.args.at(1))
                                  .arg(set->identity.productCode, 8, 16, QLatin1Char('0'))
                                  .arg(code->toULongLong(), 8, 16, QLatin1Char('0'))));
    }
    ParameterRestore runner(session.connection());
    runner.setParameterSet(set.value());
    runner.setSelection(only);
    runner.setVerify(!(c.parser && c.parser->isSet(kNoVerify)));
    runner.setStoreAfterwards(c.parser && c.parser->isSet(kStore));
    QEventLoop loop;
    QObject::connect(&runner, &ParameterRestore::finished, &loop, &QEventLoop::quit);
    if (c.options.verbose)
        QObject::connect(&runner, &ParameterRestore::progress, &loop, [&c](int done, int total) {
            if (done == total || done % 25 == 0)
                c.err << "step " << done << "/" << total << Qt::endl;
        });
    runner.start();
    loop.exec();
    const RestoreReport &report = runner.report();
    c.out << report.summary() << Qt::endl;
    if (report.succeeded())
        return ExitOk;
    return report.error.isError() ? exitCodeFor(report.error) : ExitFailure;
}

int diff(Context &c)
{
    QList<ParameterSet> sides;
    std::unique_ptr<ObjectDictionary> dictionary;
    for (const QString &side : c.args) {
        if (!isUri(side)) {
            auto loaded = ParameterSet::load(side);
            if (!loaded)
                return failFile(c, loaded.error());
            sides.append(loaded.value());
            continue;
        }
        Session session(c.registry, c.options);
        auto set = backupFrom(c, session, side, ParameterBackup::Scope::Storable);
        if (!set)
            return fail(c, set.error());
        if (!dictionary)
            dictionary = std::make_unique<ObjectDictionary>(session.connection()->dictionary());
        sides.append(set.value());
    }
    const ParameterComparison comparison = compareParameterSets(sides, c.args, dictionary.get());
    const auto format = c.options.hex ? codec::TextFormat::Hex : codec::TextFormat::Decimal;
    for (const CompareRow &row : comparison.rows) {
        if (!row.differs)
            continue;
        c.out << compareStatusName(row.status).leftJustified(8) << row.address.toString() << "  "
              << printable(row.name) << ": " << printable(row.valueText(0, format)) << " | "
              << printable(row.valueText(1, format));
        if (!row.unit.isEmpty())
            c.out << ' ' << printable(row.unit);
        c.out << Qt::endl;
    }
    c.out << comparison.rows.size() << " objects: " << comparison.countsText() << Qt::endl;
    return comparison.identical() ? ExitOk : ExitFailure;
}

int dump(Context &c)
{
    Session session(c.registry, c.options);
    const auto set = backupFrom(c, session, c.args.at(0), ParameterBackup::Scope::Readable);
    if (!set)
        return fail(c, set.error());
    const ObjectDictionary &dict = session.connection()->dictionary();
    const auto format = c.options.hex ? codec::TextFormat::Hex : codec::TextFormat::Decimal;
    qsizetype width = 0;
    for (const ParameterEntry &e : set->entries())
        width = qMax(width, printable(e.name).size());
    for (const ParameterEntry &e : set->entries()) {
        const ObjectDef *def = dict.find(e.address);
        c.out << e.address.toString().leftJustified(8) << printable(e.name).leftJustified(width)
              << " = "
              << printable(def ? def->displayText(e.raw, format)
                               : codec::toText(e.type, e.raw, format))
              << Qt::endl;
    }
    return ExitOk;
}

} // namespace db::cli
