// drivebench-cli commands in-process against a registry with a fake protocol whose addresses are
// decimal NUMBER:DATASET: what the user types reaches the connection as that parameter, and
// every address printed is written the same way. A CANopen-format protocol beside it still
// reads the same text as hex.
#include "commands.h"
#include "commands_params.h"
#include "commands_record.h"
#include "core/valuecodec.h"
#include "fakeconnection.h"
#include "parameters/parameterset.h"

#include <QBuffer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace db;

namespace {

// Parameter 372 data set 2 and the object 0x372:2 hold different values, so that a read of the
// wrong one shows.
constexpr ObjectAddress kParameter { 372, 2 };
constexpr ObjectAddress kHexTwin { 0x372, 2 };

ObjectDictionary fakeDictionary()
{
    ObjectDictionary dictionary;
    for (const ObjectAddress a : { kParameter, kHexTwin }) {
        ObjectDef def;
        def.address = a;
        def.name = a == kParameter ? QStringLiteral("Acceleration") : QStringLiteral("Hex twin");
        def.type = DataType::Unsigned16;
        def.access = Access::ReadWrite;
        def.storable = true;
        dictionary.insert(def);
    }
    return dictionary;
}

ProtocolInfo fakeProtocol(const QString &scheme, const AddressFormat *format,
                          std::function<void(test::FakeConnection &)> setUp)
{
    ProtocolInfo info;
    info.scheme = scheme;
    info.key = scheme;
    info.title = QStringLiteral("fake");
    info.uriPattern = scheme + QStringLiteral("://NAME");
    info.addressFormat = format;
    info.create = [format,
                   setUp](const ConnectionPlan &plan) -> Result<std::unique_ptr<DeviceConnection>> {
        auto connection = std::make_unique<test::FakeConnection>(plan.uri.toString());
        if (format)
            connection->setAddressFormat(*format);
        connection->setDictionary(fakeDictionary());
        connection->setValue(kParameter, 1234u);
        connection->setValue(kHexTwin, 999u);
        setUp(*connection);
        return std::unique_ptr<DeviceConnection>(std::move(connection));
    };
    return info;
}

struct Run
{
    int code = -1;
    QString out;
    QString err;
};

} // namespace

class TestCliAddressFormat : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void readsTheParameterTheUserNamed();
    void sameTextIsHexForCanopen();
    void verboseReadAndWritePrintDecimal();
    void errorsNameTheParameter();
    void wrongFormIsAUsageErrorBeforeConnecting();
    void listProtocolsShowsTheForm();
    void dumpPrintsDecimalAddresses();
    void restoreOnlyParsesDecimal();
    void recordObjParsesDecimal();
    void restoreRefusesASetOfAnotherFormat();
    void diffPrintsDecimalAddresses();

private:
    Run run(const QString &command, const QStringList &args, const QStringList &options = {},
            const QString &output = {});

    ProtocolRegistry m_registry;
    std::function<void(test::FakeConnection &)> m_setUp;
    int m_opened = 0;
    QTemporaryDir m_dir;
};

void TestCliAddressFormat::init()
{
    m_opened = 0;
    m_setUp = [](test::FakeConnection &) {
    };
    m_registry = ProtocolRegistry();
    auto setUp = [this](test::FakeConnection &c) {
        ++m_opened;
        m_setUp(c);
    };
    m_registry.add(fakeProtocol(QStringLiteral("fakeparam"), &AddressFormat::parameter(), setUp));
    m_registry.add(fakeProtocol(QStringLiteral("fakehex"), nullptr, setUp));
}

Run TestCliAddressFormat::run(const QString &command, const QStringList &args,
                              const QStringList &options, const QString &output)
{
    const cli::Command *found = nullptr;
    for (const cli::Command &c : cli::commands()) {
        if (command == QLatin1String(c.name))
            found = &c;
    }
    Run r;
    if (!found)
        return r;
    QCommandLineParser parser;
    if (found->options)
        parser.addOptions(found->options());
    // --verbose is a global option (Context::options), the rest are the command's own.
    QStringList own = options;
    own.removeAll(QStringLiteral("--verbose"));
    if (!parser.parse(QStringList { QStringLiteral("drivebench-cli") } + own))
        return r;
    QString outText;
    QString errText;
    QTextStream out(&outText);
    QTextStream err(&errText);
    cli::Context context { m_registry, cli::Options {}, args, out, err, QString() };
    context.options.connectTimeoutMs = 2000;
    context.options.verbose = options.contains(QStringLiteral("--verbose"));
    context.output = output;
    context.parser = &parser;
    r.code = found->run(context);
    out.flush();
    err.flush();
    r.out = outText;
    r.err = errText;
    return r;
}

void TestCliAddressFormat::readsTheParameterTheUserNamed()
{
    const Run r = run(QStringLiteral("read"), { QStringLiteral("fakeparam://drive"), "372:2" });
    QVERIFY2(r.code == cli::ExitOk, qPrintable(r.err));
    QCOMPARE(r.out.trimmed(), QStringLiteral("1234"));
    // A number alone is data set 0, which the fake does not have: named in decimal.
    const Run zero = run(QStringLiteral("read"), { QStringLiteral("fakeparam://drive"), "372" });
    QCOMPARE(zero.code, int(cli::ExitDeviceError));
    QVERIFY2(zero.err.contains(QLatin1String("372:0")), qPrintable(zero.err));
}

void TestCliAddressFormat::sameTextIsHexForCanopen()
{
    const Run r = run(QStringLiteral("read"), { QStringLiteral("fakehex://drive"), "372:2" });
    QVERIFY2(r.code == cli::ExitOk, qPrintable(r.err));
    QCOMPARE(r.out.trimmed(), QStringLiteral("999"));
}

void TestCliAddressFormat::verboseReadAndWritePrintDecimal()
{
    const Run read = run(QStringLiteral("read"), { QStringLiteral("fakeparam://drive"), "372:2" },
                         { QStringLiteral("--verbose") });
    QVERIFY2(read.code == cli::ExitOk, qPrintable(read.err));
    QVERIFY2(read.out.startsWith(QLatin1String("372:2 Acceleration = 1234")), qPrintable(read.out));
    const Run write =
        run(QStringLiteral("write"), { QStringLiteral("fakeparam://drive"), "372:2", "77" },
            { QStringLiteral("--verbose") });
    QVERIFY2(write.code == cli::ExitOk, qPrintable(write.err));
    QVERIFY2(write.out.startsWith(QLatin1String("372:2 <- 77")), qPrintable(write.out));
}

void TestCliAddressFormat::errorsNameTheParameter()
{
    m_setUp = [](test::FakeConnection &c) {
        c.setFailure(kParameter, Error(Error::Kind::DeviceError, QStringLiteral("refused")));
    };
    const Run r =
        run(QStringLiteral("write"), { QStringLiteral("fakeparam://drive"), "372:2", "5" });
    QCOMPARE(r.code, int(cli::ExitDeviceError));
    QVERIFY2(r.err.contains(QLatin1String("writing 372:2")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("refused")), qPrintable(r.err));
}

void TestCliAddressFormat::wrongFormIsAUsageErrorBeforeConnecting()
{
    const Run r = run(QStringLiteral("read"), { QStringLiteral("fakeparam://drive"), "6041:0A" });
    QCOMPARE(r.code, int(cli::ExitUsage));
    QVERIFY2(r.err.contains(QLatin1String("NUMBER:DATASET")), qPrintable(r.err));
    QCOMPARE(m_opened, 0);
    // A bad URI is the cause named, not the address.
    const Run uri = run(QStringLiteral("read"), { QStringLiteral("nowhere://drive"), "372:2" });
    QCOMPARE(uri.code, int(cli::ExitUsage));
    QVERIFY2(uri.err.contains(QLatin1String("unknown protocol")), qPrintable(uri.err));
}

void TestCliAddressFormat::listProtocolsShowsTheForm()
{
    const Run r = run(QStringLiteral("list-protocols"), {});
    QCOMPARE(r.code, int(cli::ExitOk));
    const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 2);
    for (const QString &line : lines) {
        const bool param = line.startsWith(QLatin1String("fakeparam"));
        QVERIFY2(line.endsWith(param ? QLatin1String("addresses like 372:2")
                                     : QLatin1String("addresses like 6041:0")),
                 qPrintable(line));
    }
}

void TestCliAddressFormat::dumpPrintsDecimalAddresses()
{
    const Run r = run(QStringLiteral("dump"), { QStringLiteral("fakeparam://drive") });
    QVERIFY2(r.code == cli::ExitOk, qPrintable(r.err));
    QVERIFY2(r.out.contains(QLatin1String("372:2")), qPrintable(r.out));
    QVERIFY2(r.out.contains(QLatin1String("882:2")), qPrintable(r.out)); // 0x372 in decimal
    QVERIFY2(!r.out.contains(QLatin1String("0174:2")), qPrintable(r.out)); // 372 in hex
}

void TestCliAddressFormat::restoreOnlyParsesDecimal()
{
    // --only is checked against the file before anything is connected.
    ParameterSet set;
    set.addressFormat = &AddressFormat::parameter();
    set.insert({ kHexTwin, QStringLiteral("Hex twin"), DataType::Unsigned16,
                 codec::normalize(DataType::Unsigned16, 5u).value(), QString() });
    const QString file = m_dir.filePath(QStringLiteral("twin.dbp"));
    QVERIFY(set.save(file).ok());
    const Run r = run(QStringLiteral("restore"), { QStringLiteral("fakeparam://drive"), file },
                      { QStringLiteral("--only"), QStringLiteral("372:2") });
    QCOMPARE(r.code, int(cli::ExitUsage));
    QVERIFY2(r.err.contains(QLatin1String("372:2 is not in")), qPrintable(r.err));
    QCOMPARE(m_opened, 0);
    const Run bad = run(QStringLiteral("restore"), { QStringLiteral("fakeparam://drive"), file },
                        { QStringLiteral("--only"), QStringLiteral("0x372:2") });
    QCOMPARE(bad.code, int(cli::ExitUsage));
    QVERIFY2(bad.err.contains(QLatin1String("NUMBER:DATASET")), qPrintable(bad.err));
}

void TestCliAddressFormat::restoreRefusesASetOfAnotherFormat()
{
    // The same file lines would name other objects on this device: refused before connecting.
    ParameterSet set;
    set.insert({ kHexTwin, QStringLiteral("Hex twin"), DataType::Unsigned16,
                 codec::normalize(DataType::Unsigned16, 5u).value(), QString() });
    const QString file = m_dir.filePath(QStringLiteral("hex.dbp"));
    QVERIFY(set.save(file).ok());
    const Run r = run(QStringLiteral("restore"), { QStringLiteral("fakeparam://drive"), file });
    QCOMPARE(r.code, int(cli::ExitUsage));
    QVERIFY2(r.err.contains(QLatin1String("canopen addresses")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("parameter addresses")), qPrintable(r.err));
    QCOMPARE(m_opened, 0);
    // diff refuses to compare them.
    const Run diff = run(QStringLiteral("diff"), { QStringLiteral("fakeparam://drive"), file });
    QCOMPARE(diff.code, int(cli::ExitUsage));
    QVERIFY2(diff.err.contains(QLatin1String("cannot be compared")), qPrintable(diff.err));
}

void TestCliAddressFormat::diffPrintsDecimalAddresses()
{
    ParameterSet set;
    set.addressFormat = &AddressFormat::parameter();
    set.insert({ kParameter, QStringLiteral("Acceleration"), DataType::Unsigned16,
                 codec::normalize(DataType::Unsigned16, 1200u).value(), QString() });
    set.insert({ kHexTwin, QStringLiteral("Hex twin"), DataType::Unsigned16,
                 codec::normalize(DataType::Unsigned16, 999u).value(), QString() });
    const QString file = m_dir.filePath(QStringLiteral("decimal.dbp"));
    QVERIFY(set.save(file).ok());
    const Run r = run(QStringLiteral("diff"), { QStringLiteral("fakeparam://drive"), file });
    QCOMPARE(r.code, int(cli::ExitFailure)); // they differ
    QVERIFY2(r.out.contains(QLatin1String("changed 372:2  Acceleration: 1234 | 1200")),
             qPrintable(r.out));
    QVERIFY2(!r.out.contains(QLatin1String("882:2")), qPrintable(r.out)); // equal on both sides
}

void TestCliAddressFormat::recordObjParsesDecimal()
{
    const QString csv = m_dir.filePath(QStringLiteral("x.csv"));
    const Run bad = run(QStringLiteral("record"), { QStringLiteral("fakeparam://drive") },
                        { QStringLiteral("--obj"), QStringLiteral("60FD:0"),
                          QStringLiteral("--duration"), QStringLiteral("1") },
                        csv);
    QCOMPARE(bad.code, int(cli::ExitUsage));
    QVERIFY2(bad.err.contains(QLatin1String("NUMBER:DATASET")), qPrintable(bad.err));
    const Run twice = run(QStringLiteral("record"), { QStringLiteral("fakeparam://drive") },
                          { QStringLiteral("--obj"), QStringLiteral("372:2,0372.2"),
                            QStringLiteral("--duration"), QStringLiteral("1") },
                          csv);
    QCOMPARE(twice.code, int(cli::ExitUsage));
    QVERIFY2(twice.err.contains(QLatin1String("--obj 372:2 given twice")), qPrintable(twice.err));
    QCOMPARE(m_opened, 0);
    // A recording of parameter 372 data set 2 names its column so, and triggers find it.
    const Run ok = run(QStringLiteral("record"), { QStringLiteral("fakeparam://drive") },
                       { QStringLiteral("--obj"), QStringLiteral("372:2"),
                         QStringLiteral("--rate-ms"), QStringLiteral("20"),
                         QStringLiteral("--trigger"), QStringLiteral("0372.2,above,1000"),
                         QStringLiteral("--pre"), QStringLiteral("0"), QStringLiteral("--post"),
                         QStringLiteral("0.2"), QStringLiteral("--wait"), QStringLiteral("0.3") },
                       csv);
    QVERIFY2(ok.out.contains(QLatin1String("armed: waiting for 0372.2,above,1000")),
             qPrintable(ok.out + ok.err));
    const Run recorded =
        run(QStringLiteral("record"), { QStringLiteral("fakeparam://drive") },
            { QStringLiteral("--obj"), QStringLiteral("372:2"), QStringLiteral("--rate-ms"),
              QStringLiteral("20"), QStringLiteral("--duration"), QStringLiteral("0.2") },
            csv);
    QVERIFY2(recorded.code == cli::ExitOk, qPrintable(recorded.err));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    QVERIFY2(text.contains("# channel: 372:2; name: Acceleration;"), text.constData());
    QVERIFY2(text.contains("; addresses: parameter"), text.constData());
}

QTEST_GUILESS_MAIN(TestCliAddressFormat)
#include "tst_cli_addressformat.moc"
