#include "commands_params.h"

#include "core/printable.h"
#include "parameters/parameterrunner.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFileInfo>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

namespace {

const QString kOnly = QStringLiteral("only");
const QString kStore = QStringLiteral("store");
const QString kNoVerify = QStringLiteral("no-verify");
const QString kIgnoreIdentity = QStringLiteral("ignore-identity");

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

// What a backup run gave: every object read, and the error when that is not the complete set
// (result() of the runner: any object failed, nothing read, or the run stopped).
struct BackupRun
{
    ParameterSet read;
    Error error;
    QList<BackupFailure> failures;
    int objects = 0; // objects asked for
};

// Opens uri in session and runs a backup to its end in a local event loop (the CLI is
// synchronous by design). A device without a description has nothing to back up: usage error.
// Each object that could not be read is a "warning:" line on stderr.
Result<BackupRun> backupFrom(Context &c, Session &session, const QString &uri,
                             ParameterBackup::Scope scope)
{
    if (auto opened = session.open(uri); !opened)
        return opened.error();
    DeviceConnection *connection = session.connection();
    if (connection->dictionary().isEmpty())
        return usage(Tr::tr("no device description for %1: give ?eds=FILE")
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
        c.err << Tr::tr("warning: %1").arg(printable(warning)) << Qt::endl;
    for (const BackupFailure &skipped : backup.skipped())
        c.err << Tr::tr("skipped: %1").arg(printable(skipped.text())) << Qt::endl;
    const auto result = backup.result();
    return BackupRun { backup.partialSet(), result ? Error() : result.error(), backup.failures(),
                       backup.objectCount() };
}

// The partial file of a backup that failed: what was read, and one comment line per object
// that was not, so that it can be inspected, diffed and (deliberately) restored.
QStringList partialComments(const BackupRun &run)
{
    QStringList lines {
        Tr::tr("partial backup: %1 of %2 objects could not be read; not a complete set")
            .arg(run.failures.size())
            .arg(run.objects),
    };
    for (const BackupFailure &f : run.failures)
        lines.append(QStringLiteral("failed ") + f.text());
    return lines;
}

// A set may only go to the product it was made for: names (when both are known) and the
// product code the device reports in 1018h.2 must match. A set that does not know its product
// code (the backup could not read it), or a device whose 1018h.2 cannot be read, cannot be
// checked: refused, --ignore-identity overrides.
Result<void> checkIdentity(Context &c, Session &session, const ParameterSet &set)
{
    const QString &file = c.args.at(1);
    const QString &uri = c.args.at(0);
    const DeviceIdentity &device = session.connection()->dictionary().identity;
    if (!set.identity.productName.isEmpty() && !device.productName.isEmpty()
        && set.identity.productName != device.productName)
        return usage(Tr::tr("%1 is a set for '%2', but %3 is a '%4'")
                         .arg(file, set.identity.productName, uri, device.productName));
    if (!set.productCodeKnown)
        return usage(Tr::tr("%1 does not record the product code (1018h.2 could not be "
                            "read when it was made), so it cannot be checked against "
                            "the device; give --ignore-identity to restore it anyway")
                         .arg(file));
    if (!session.connection()->dictionary().contains(ObjectAddress(0x1018, 2)))
        return {};
    const auto code = session.read({ 0x1018, 2 });
    if (!code)
        return code.error().prefixed(Tr::tr("cannot check the device's product code (1018h.2); "
                                            "--ignore-identity restores without the check"));
    if (code->toULongLong() != set.identity.productCode)
        return usage(Tr::tr("%1 is a set for product code 0x%2, but the device reports 0x%3")
                         .arg(file)
                         .arg(set.identity.productCode, 8, 16, QLatin1Char('0'))
                         .arg(code->toULongLong(), 8, 16, QLatin1Char('0')));
    // The same product, but is it the same unit? Calibrations and offsets belong to one.
    if (set.serialNumber.isEmpty()
        || !session.connection()->dictionary().contains(ObjectAddress(0x1018, 4)))
        return {};
    const auto serial = session.read({ 0x1018, 4 });
    if (!serial)
        return serial.error().prefixed(Tr::tr("cannot check the device's serial number "
                                              "(1018h.4); --ignore-identity restores without "
                                              "the check"));
    const QString reported = ParameterSet::identityNumber(quint32(serial->toULongLong()));
    if (reported.compare(set.serialNumber, Qt::CaseInsensitive) != 0)
        return usage(Tr::tr("%1 was read from another unit (serial number %2), the device "
                            "reports %3; give --ignore-identity to restore it to this unit")
                         .arg(file, set.serialNumber, reported));
    return {};
}

// An empty set that stands for the addresses of a device (for checkSameAddressFormat()).
ParameterSet addressSet(const AddressFormat &format)
{
    ParameterSet set;
    set.addressFormat = &format;
    return set;
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
                           Tr::tr("restore: only these objects, as the protocol writes "
                                  "addresses, e.g. 6083:0,6084:0."),
                           QStringLiteral("ADDRESS,...")),
        QCommandLineOption(kStore,
                           Tr::tr("restore: store to non-volatile memory afterwards "
                                  "(1010h sub 1 = \"save\") when every row verified.")),
        QCommandLineOption(kNoVerify, Tr::tr("restore: do not read each object back.")),
        QCommandLineOption(kIgnoreIdentity,
                           Tr::tr("restore: skip the product check (a set from another "
                                  "product, or one whose product code is unknown).")),
    };
}

int backup(Context &c)
{
    if (c.output.isEmpty())
        return fail(c, usage(Tr::tr("backup needs the output file: -o FILE")));
    Session session(c.registry, c.options);
    const auto run = backupFrom(c, session, c.args.at(0), ParameterBackup::Scope::Storable);
    if (!run)
        return fail(c, run.error());
    if (!run->error.isError()) {
        if (auto saved = run->read.save(c.output); !saved)
            return failFile(c, saved.error());
        c.out << "backed up " << run->read.size() << " objects from " << printable(run->read.source)
              << " to " << printable(c.output) << Qt::endl;
        return ExitOk;
    }
    // Never replace a file with less than a complete set: the output stays as it was, and what
    // was read goes beside it with the failures listed.
    QString where = Tr::tr("nothing was written");
    if (!run->failures.isEmpty()) {
        const QString partial = c.output + QStringLiteral(".partial");
        if (auto saved = run->read.save(partial, partialComments(*run)); saved)
            where = Tr::tr("the %1 objects read and the failures are in %2")
                        .arg(run->read.size())
                        .arg(partial);
        else
            where = saved.error().message();
    }
    return fail(
        c,
        run->error.prefixed(Tr::tr("backup incomplete, %1 not written (%2)").arg(c.output, where)));
}

int restore(Context &c)
{
    // The file first: a corrupt or foreign file must be refused before anything is connected.
    const auto set = ParameterSet::load(c.args.at(1));
    if (!set)
        return failFile(c, set.error());
    if (set->isEmpty())
        return fail(c, usage(Tr::tr("%1 holds no object: nothing to restore").arg(c.args.at(1))));
    // The set's addresses must be written as the device at the URI writes them, and --only
    // names objects in that format too; both are checked before anything is connected.
    const auto format = addressFormatFor(c.registry, c.args.at(0));
    if (!format)
        return fail(c, format.error());
    if (auto same =
            checkSameAddressFormat({ *set, addressSet(**format) }, { c.args.at(1), c.args.at(0) });
        !same)
        return fail(c, same.error());
    QList<ObjectAddress> only;
    if (c.parser && c.parser->isSet(kOnly)) {
        for (const QString &part : c.parser->value(kOnly).split(u',', Qt::SkipEmptyParts)) {
            const auto address = (*format)->parse(part.trimmed());
            if (!address)
                return fail(c, usage(QStringLiteral("--only: %1").arg(address.error().message())));
            if (!set->contains(*address))
                return fail(c,
                            usage(Tr::tr("--only: %1 is not in %2")
                                      .arg((*format)->format(*address), c.args.at(1))));
            only.append(*address);
        }
        if (only.isEmpty())
            return fail(
                c, usage(Tr::tr("--only needs addresses like %1,...").arg((*format)->example())));
    }
    Session session(c.registry, c.options);
    if (auto opened = session.open(c.args.at(0)); !opened)
        return fail(c, opened.error());
    if (c.parser && c.parser->isSet(kIgnoreIdentity))
        c.err << Tr::tr("warning: --ignore-identity: the set's product is not checked against "
                        "the device")
              << Qt::endl;
    else if (auto checked = checkIdentity(c, session, *set); !checked)
        return fail(c, checked.error());
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
    Error readError;
    for (const QString &side : c.args) {
        if (!isUri(side)) {
            auto loaded = ParameterSet::load(side);
            if (!loaded)
                return failFile(c, loaded.error());
            sides.append(loaded.value());
            continue;
        }
        Session session(c.registry, c.options);
        auto run = backupFrom(c, session, side, ParameterBackup::Scope::Storable);
        if (!run)
            return fail(c, run.error());
        if (run->read.isEmpty())
            return fail(c, run->error);
        // Objects that could not be read would show as missing: compare the rest, then fail.
        if (run->error.isError() && !readError.isError())
            readError = run->error.prefixed(Tr::tr("reading %1").arg(side));
        if (!dictionary)
            dictionary = std::make_unique<ObjectDictionary>(session.connection()->dictionary());
        sides.append(run->read);
    }
    if (auto same = checkSameAddressFormat(sides, c.args); !same)
        return fail(c, same.error());
    const ParameterComparison comparison = compareParameterSets(sides, c.args, dictionary.get());
    const auto format = c.options.hex ? codec::TextFormat::Hex : codec::TextFormat::Decimal;
    for (const CompareRow &row : comparison.rows) {
        if (!row.differs)
            continue;
        // As the editor shows them: physical values with the parameter's decimals.
        const ObjectDef *def = dictionary ? dictionary->find(row.address) : nullptr;
        const auto text = [&](int side) {
            const QVariant v = row.values.value(side);
            return def && v.isValid() ? def->displayText(v, format) : row.valueText(side, format);
        };
        c.out << compareStatusName(row.status).leftJustified(8)
              << comparison.addressFormat->format(row.address) << "  " << printable(row.name)
              << ": " << printable(text(0)) << " | " << printable(text(1));
        // displayText() names the unit itself, except for hexadecimal raw values.
        if ((!def || format == codec::TextFormat::Hex) && !row.unit.isEmpty())
            c.out << ' ' << printable(row.unit);
        c.out << Qt::endl;
    }
    c.out << comparison.rows.size() << " objects: " << comparison.countsText() << Qt::endl;
    if (readError.isError())
        return fail(c, readError);
    return comparison.identical() ? ExitOk : ExitFailure;
}

int dump(Context &c)
{
    Session session(c.registry, c.options);
    const auto run = backupFrom(c, session, c.args.at(0), ParameterBackup::Scope::Readable);
    if (!run)
        return fail(c, run.error());
    const ObjectDictionary &dict = session.connection()->dictionary();
    const AddressFormat &addressFormat = session.connection()->addressFormat();
    const auto format = c.options.hex ? codec::TextFormat::Hex : codec::TextFormat::Decimal;
    qsizetype width = 0;
    for (const ParameterEntry &e : run->read.entries())
        width = qMax(width, printable(e.name).size());
    for (const ParameterEntry &e : run->read.entries()) {
        const ObjectDef *def = dict.find(e.address);
        c.out << addressFormat.format(e.address).leftJustified(8)
              << printable(e.name).leftJustified(width) << " = "
              << printable(def ? def->displayText(e.raw, format)
                               : codec::toText(e.type, e.raw, format))
              << Qt::endl;
    }
    // What could be read is printed; the objects that could not are the warnings above.
    if (run->error.isError())
        return fail(c, run->error);
    return ExitOk;
}

} // namespace db::cli
