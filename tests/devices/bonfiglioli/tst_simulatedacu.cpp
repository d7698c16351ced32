// Level 3: the simulated ACU over loopback TCP, driven by the VABus client: the example
// values, every error code it produces, data sets and RAM, the EEPROM counter, block access,
// network parameters, system bus slaves, one PLC connection, the watchdog, failure modes.

#include "devices/bonfiglioli/acudescription.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "transport/tcpstream.h"
#include "vabus/vabusclient.h"
#include "wait.h"

#include <cmath>

#include <QSignalSpy>
#include <QTcpSocket>
#include <QtTest>

#include <memory>

using namespace db;
using db::test::await;
using namespace db::vabus;
using db::bonfiglioli::SimulatedAcu;

namespace {

// Parameters of the index groups (selected through 1200/1201 and the other index parameters).
bool isIndexed(quint16 p)
{
    return (p >= 1200 && p <= 1265) || (p >= 1341 && p <= 1352) || (p >= 1420 && p <= 1422);
}

quint32 codeOf(const Result<QVariant> &result)
{
    return result.ok() ? 0 : result.error().deviceCode();
}

} // namespace

class TstSimulatedAcu : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init()
    {
        m_acu = std::make_unique<SimulatedAcu>();
        QVERIFY(m_acu->listen(0).ok());
        m_stream = std::make_unique<TcpStream>(QStringLiteral("127.0.0.1"), m_acu->port());
        m_client = std::make_unique<VabusClient>(m_stream.get());
        m_client->setKeepAliveIdleMs(0);
        m_client->setTimeoutMs(500);
        m_stream->open();
        QTRY_VERIFY(m_stream->isOpen());
    }
    void cleanup()
    {
        m_client.reset();
        m_stream.reset();
        m_acu.reset();
    }

    void exampleValues()
    {
        QCOMPARE(await(m_client->read(372, 2, DataType::Unsigned16)).value(),
                 QVariant(qulonglong(1390)));
        QCOMPARE(await(m_client->read(481, 1, DataType::Integer32)).value(),
                 QVariant(qlonglong(1000)));
        QCOMPARE(await(m_client->read(12, 0)).value(), QVariant(QStringLiteral("5.3.2 STO")));
        QVERIFY(await(m_client->write(376, 4, DataType::Unsigned16, qulonglong(15))).ok());
        QCOMPARE(codeOf(await(m_client->write(376, 4, DataType::Unsigned16, qulonglong(0)))), 1u);
        QVERIFY(await(m_client->write(482, 9, DataType::Integer32, qlonglong(4450))).ok());
        QCOMPARE(codeOf(await(m_client->write(482, 9, DataType::Integer32, qlonglong(200000)))),
                 1u);
        QCOMPARE(await(m_client->read(11, 0)).value(), QVariant(qlonglong(1))); // last error
    }

    void errorCodes()
    {
        QCOMPARE(codeOf(await(m_client->read(372, 5))), 0u); // refused before sending
        QCOMPARE(codeOf(await(m_client->read(12, 2))), 2u); // single parameter, DS 2
        QCOMPARE(codeOf(await(m_client->writeData(12, 0, "x"))), 4u); // read-only
        QCOMPARE(codeOf(await(m_client->read(18, 0))), 3u); // write-only
        QCOMPARE(codeOf(await(m_client->read(481, 0))), 9u); // data sets differ
        QCOMPARE(codeOf(await(m_client->read(1599, 0))), 11u);
        QCOMPARE(codeOf(await(m_client->writeData(482, 9, QByteArray::fromHex("6211")))), 14u);
        QCOMPARE(codeOf(await(m_client->writeData(372, 2, {}))), 14u); // a word without data
        QCOMPARE(codeOf(await(m_client->write(411, 0, DataType::Unsigned16, qulonglong(1)))), 4u);
        // Not writable while running.
        QVERIFY(enableOperation());
        QCOMPARE(await(m_client->read(411, 0)).value(), QVariant(qlonglong(0x0237)));
        QCOMPARE(codeOf(await(m_client->write(372, 1, DataType::Unsigned16, qulonglong(1400)))),
                 8u);
        QVERIFY(await(m_client->write(410, 5, DataType::Unsigned16, qulonglong(0x0007))).ok());
        QVERIFY(await(m_client->write(372, 1, DataType::Unsigned16, qulonglong(1400))).ok());
        // Unknown system bus node.
        m_client->setSys(0x47);
        QCOMPARE(codeOf(await(m_client->read(12, 0))), 20u);
    }

    void syntaxErrorAnswered()
    {
        QTcpSocket raw;
        raw.connectToHost(QStringLiteral("127.0.0.1"), m_acu->port());
        // The client holds the PLC port; take it over.
        QSignalSpy log(&m_acu->server(), &Server::logLine);
        QTRY_COMPARE(log.size(), 1);
        QVERIFY(log.at(0).at(0).toString().contains(QLatin1String("refusing")));
        QTRY_COMPARE(raw.state(), QAbstractSocket::UnconnectedState);
        m_client.reset();
        m_stream.reset();
        QTRY_VERIFY(!m_acu->server().hasClient());
        raw.connectToHost(QStringLiteral("127.0.0.1"), m_acu->port());
        QVERIFY(raw.waitForConnected(3000));
        raw.write(QByteArray::fromHex("010400027401")); // header bits 5..0 set
        QTRY_COMPARE(raw.bytesAvailable(), 8);
        QCOMPARE(raw.readAll().toHex(' '), QByteArray("40 06 00 02 74 01 0d 00"));
    }

    // Every value the simulator starts with is one it accepts back (a restore of a fresh backup).
    void defaultsAreWithinTheirLimits()
    {
        const ObjectDictionary &d = bonfiglioli::acuDictionary();
        for (const ObjectDef &def : d.objects()) {
            if (!def.writable() || !def.readable() || def.address.index == 17
                || def.address.index == 18 || def.address.index == 410 || def.address.index == 1437
                || isIndexed(def.address.index))
                continue;
            const QVariant raw = m_acu->store().value(
                def.address.index,
                def.address.sub == 0 && bonfiglioli::hasDataSets(d, def.address.index)
                    ? 1
                    : def.address.sub);
            const auto data = encodeValue(def.type, raw);
            QVERIFY2(data.ok(), qPrintable(def.name));
            const quint64 before = m_acu->eepromWrites();
            const auto outcome =
                m_acu->store().write(def.address.index, def.address.sub, data.value());
            QVERIFY2(outcome.error == 0,
                     qPrintable(QStringLiteral("%1 %2: error %3")
                                    .arg(def.address.index)
                                    .arg(def.name)
                                    .arg(outcome.error)));
            QCOMPARE(m_acu->eepromWrites(), before + 1);
        }
    }

    void dataSetsRamAndEepromCounter()
    {
        const quint64 before = m_acu->eepromWrites();
        QVERIFY(await(m_client->write(481, 0, DataType::Integer32, qlonglong(1234))).ok());
        QCOMPARE(m_acu->eepromWrites(), before + 1);
        QCOMPARE(await(m_client->read(481, 0, DataType::Integer32)).value(),
                 QVariant(qlonglong(1234)));
        // RAM writes, keep-alives and reads do not touch the EEPROM.
        for (int i = 0; i < 5; ++i)
            QVERIFY(await(m_client->write(481, 7, DataType::Integer32, qlonglong(i))).ok());
        QVERIFY(await(m_client->write(410, 5, DataType::Unsigned16, qulonglong(0))).ok());
        QCOMPARE(await(m_client->read(481, 2, DataType::Integer32)).value(),
                 QVariant(qlonglong(4)));
        QCOMPARE(m_acu->eepromWrites(), before + 1);
        m_acu->powerCycle();
        QCOMPARE(await(m_client->read(481, 2, DataType::Integer32)).value(),
                 QVariant(qlonglong(1234)));
    }

    void blockAccess()
    {
        QVERIFY(await(m_client->writeData(17, 0, "002100021100213")).ok());
        QCOMPARE(await(m_client->read(19, 0)).value(),
                 QVariant(QStringLiteral("00002A5D00660028")));
        QVERIFY(await(m_client->writeData(17, 0, "0048100482")).ok());
        QVERIFY(await(m_client->writeData(18, 0, "0000303E000010F9")).ok());
        QCOMPARE(await(m_client->read(481, 1, DataType::Integer32)).value(),
                 QVariant(qlonglong(12350)));
        QCOMPARE(await(m_client->read(482, 0, DataType::Integer32)).value(),
                 QVariant(qlonglong(4345)));
        QCOMPARE(codeOf(await(m_client->writeData(17, 0, "00012"))), 1u); // a string
        m_acu->powerCycle(); // the definition is volatile
        QCOMPARE(codeOf(await(m_client->read(19, 0))), 1u);
    }

    void indexParameters()
    {
        const quint64 before = m_acu->eepromWrites();
        // T20/T21: 1202 = 30000 into RAM index 1 (34 = 33 + 1).
        QVERIFY(await(m_client->write(1200, 0, DataType::Integer16, qlonglong(34))).ok());
        QVERIFY(await(m_client->write(1202, 0, DataType::Integer32, qlonglong(30000))).ok());
        QCOMPARE(m_acu->eepromWrites(), before);
        // T22-T24: select index 1 for reading, then read.
        QVERIFY(await(m_client->write(1201, 0, DataType::Integer16, qlonglong(1))).ok());
        QCOMPARE(await(m_client->read(1202, 0, DataType::Integer32)).value(),
                 QVariant(qlonglong(30000)));
        // Index 2 in EEPROM; index 1 is untouched.
        QVERIFY(await(m_client->write(1200, 0, DataType::Integer16, qlonglong(2))).ok());
        QVERIFY(await(m_client->write(1202, 0, DataType::Integer32, qlonglong(123000))).ok());
        QCOMPARE(m_acu->eepromWrites(), before + 1);
        QVERIFY(await(m_client->write(1201, 0, DataType::Integer16, qlonglong(2))).ok());
        QCOMPARE(await(m_client->read(1202, 0, DataType::Integer32)).value(),
                 QVariant(qlonglong(123000)));
        QCOMPARE(codeOf(await(m_client->write(1200, 0, DataType::Integer16, qlonglong(66)))), 1u);
        // 16-index group: 17 = all indices in RAM.
        QVERIFY(await(m_client->write(1250, 0, DataType::Integer16, qlonglong(17))).ok());
        QVERIFY(await(m_client->write(1252, 0, DataType::Unsigned16, qulonglong(7))).ok());
        QVERIFY(await(m_client->write(1251, 0, DataType::Integer16, qlonglong(16))).ok());
        QCOMPARE(await(m_client->read(1252, 0, DataType::Unsigned16)).value(),
                 QVariant(qulonglong(7)));
        // A power cycle loses the RAM indices and the selections.
        m_acu->powerCycle();
        QCOMPARE(codeOf(await(m_client->read(1202, 0, DataType::Integer32))), 1u);
        QVERIFY(await(m_client->write(1201, 0, DataType::Integer16, qlonglong(1))).ok());
        QCOMPARE(await(m_client->read(1202, 0, DataType::Integer32)).value(),
                 QVariant(qlonglong(0)));
        QVERIFY(await(m_client->write(1201, 0, DataType::Integer16, qlonglong(2))).ok());
        QCOMPARE(await(m_client->read(1202, 0, DataType::Integer32)).value(),
                 QVariant(qlonglong(123000)));
    }

    void networkParameters()
    {
        QVERIFY(await(m_client->read(1431, 0)).value().toString().contains(QLatin1String("MAC")));
        QVERIFY(await(m_client->write(1432, 4, DataType::Unsigned16, qulonglong(30))).ok());
        QVERIFY(await(m_client->write(1437, 0, DataType::Unsigned16, qulonglong(0))).ok());
        QCOMPARE(await(m_client->read(1432, 4, DataType::Unsigned16)).value(),
                 QVariant(qulonglong(30)));
        // An invalid netmask is refused on apply: the buffer returns to the active values.
        QVERIFY(await(m_client->write(1433, 2, DataType::Unsigned16, qulonglong(0))).ok());
        QVERIFY(await(m_client->write(1437, 0, DataType::Unsigned16, qulonglong(0))).ok());
        QCOMPARE(await(m_client->read(1433, 2, DataType::Unsigned16)).value(),
                 QVariant(qulonglong(255)));
        // Reload restores the active values into the buffer.
        QVERIFY(await(m_client->write(1432, 1, DataType::Unsigned16, qulonglong(10))).ok());
        QVERIFY(await(m_client->write(1437, 0, DataType::Unsigned16, qulonglong(1))).ok());
        QCOMPARE(await(m_client->read(1432, 1, DataType::Unsigned16)).value(),
                 QVariant(qulonglong(172)));
    }

    void systemBusSlave()
    {
        m_acu->addSystemBusSlave(7);
        m_client->setSys(0x47);
        QCOMPARE(await(m_client->read(29, 0)).value(), QVariant(QStringLiteral("ACU node 7")));
        m_client->setSys(0x48);
        QCOMPARE(codeOf(await(m_client->read(29, 0))), 20u);
        m_client->setSys(0x30);
        QCOMPARE(await(m_client->read(29, 0)).value(), QVariant(QStringLiteral("ACU simulated")));
    }

    void warningsAndFaults()
    {
        m_acu->setWarnings(0x0008);
        m_acu->setApplicationWarnings(0x0002);
        m_acu->setWarning2(true);
        QCOMPARE(await(m_client->read(270, 0)).value(), QVariant(qlonglong(qint16(0x8008))));
        QCOMPARE(await(m_client->read(274, 0)).value(), QVariant(qlonglong(2)));
        QVERIFY(await(m_client->read(411, 0)).value().toLongLong() & 0x0080);
        m_acu->raiseFault(0x1447);
        QCOMPARE(await(m_client->read(260, 0, DataType::Unsigned16)).value(),
                 QVariant(qulonglong(0x1447)));
        QVERIFY(await(m_client->read(411, 0, DataType::Unsigned16)).value().toUInt() & 0x0008);
        QVERIFY(await(m_client->write(410, 5, DataType::Unsigned16, qulonglong(0x0080))).ok());
        QCOMPARE(await(m_client->read(260, 0, DataType::Unsigned16)).value(),
                 QVariant(qulonglong(0)));
    }

    void watchdogReactsPer388_data()
    {
        QTest::addColumn<int>("reaction");
        QTest::addColumn<bool>("fault");
        QTest::addColumn<bool>("running");
        QTest::newRow("0 no reaction") << 0 << false << true;
        QTest::newRow("1 fault") << 1 << true << false;
        QTest::newRow("2 switch off") << 2 << false << false;
        QTest::newRow("5 quick stop + fault") << 5 << true << false;
    }
    void watchdogReactsPer388()
    {
        QFETCH(int, reaction);
        QFETCH(bool, fault);
        QFETCH(bool, running);
        // A long watchdog time while the drive is brought into operation, so that a slow
        // machine cannot let it run out between two of these writes; then the short one.
        QSignalSpy lost(m_acu.get(), &SimulatedAcu::communicationLost);
        m_acu->setWatchdogMs(60000);
        QVERIFY(!m_acu->isWatchdogArmed());
        QVERIFY(await(m_client->write(388, 0, DataType::Unsigned16, qulonglong(reaction))).ok());
        QVERIFY(enableOperation());
        QVERIFY(m_acu->isWatchdogArmed());
        QCOMPARE(lost.size(), 0);
        m_acu->setWatchdogMs(150); // restarts the running watchdog with the new time
        QVERIFY(lost.wait(3000));
        QCOMPARE(lost.size(), 1);
        QCOMPARE(lost.at(0).at(0).toInt(), reaction);
        QCOMPARE(m_acu->fault() == 0x2714, fault);
        QCOMPARE(m_acu->isRunning(), running);
    }

    void keepAliveHoldsWatchdogOff()
    {
        // The watchdog time is ten keep-alive intervals, so that a slow machine (a sanitizer
        // build beside other tests) does not miss it by a late timer.
        m_acu->setWatchdogMs(500);
        m_client->setKeepAliveIdleMs(50);
        QSignalSpy lost(m_acu.get(), &SimulatedAcu::communicationLost);
        const quint64 writes = m_acu->eepromWrites();
        QVERIFY(await(m_client->read(12, 0)).ok());
        QVERIFY(!lost.wait(1500)); // three watchdog times
        QCOMPARE(m_acu->fault(), quint16(0));
        QCOMPARE(m_acu->eepromWrites(), writes); // keep-alives are reads
    }

    void failureModes_data()
    {
        QTest::addColumn<int>("failure");
        QTest::addColumn<int>("kind");
        QTest::newRow("silent") << int(Server::Failure::Silent) << int(Error::Kind::Timeout);
        QTest::newRow("garbage") << int(Server::Failure::Garbage) << int(Error::Kind::Malformed);
        QTest::newRow("slow") << int(Server::Failure::Slow) << int(Error::Kind::Timeout);
        QTest::newRow("split") << int(Server::Failure::SplitBytes) << int(Error::Kind::None);
    }
    void failureModes()
    {
        QFETCH(int, failure);
        QFETCH(int, kind);
        m_client->setTimeoutMs(100);
        m_acu->server().setFailure({ Server::Failure(failure), 1000, 1 });
        const auto result = await(m_client->read(372, 2, DataType::Unsigned16));
        QCOMPARE(int(result.ok() ? Error::Kind::None : result.error().kind()), kind);
        if (result.ok())
            QCOMPARE(result.value(), QVariant(qulonglong(1390)));
    }

    void startupDelayAnswersNothing()
    {
        m_client->setTimeoutMs(100);
        m_acu->setStartupDelayMs(60000);
        QVERIFY(m_acu->isStarting());
        QCOMPARE(await(m_client->read(12, 0)).error().kind(), Error::Kind::Timeout);
        m_acu->setStartupDelayMs(0);
        QCOMPARE(await(m_client->read(12, 0)).value(), QVariant(QStringLiteral("5.3.2 STO")));
    }

    void dropAfterN()
    {
        m_acu->server().setFailure({ Server::Failure::DropAfter, 0, 2 });
        QVERIFY(await(m_client->read(12, 0)).ok());
        QVERIFY(await(m_client->read(12, 0)).ok());
        QCOMPARE(await(m_client->read(12, 0)).error().kind(), Error::Kind::Disconnected);
    }

    // The state machine's sequences (412 = 1, positioning configuration 240): each command
    // gives the inverter's status value; 0x000F straight from "switch on disabled" (4') is only
    // for configurations without positioning control.
    void stateMachineSequence()
    {
        QCOMPARE(status(), 0x0050);
        QVERIFY(control(0x000F));
        QCOMPARE(status(), 0x0050); // no 4' with 30 = 240
        QVERIFY(control(0x0006));
        QCOMPARE(status(), 0x0031);
        QVERIFY(control(0x0007));
        QCOMPARE(status(), 0x0033);
        QVERIFY(control(0x000F));
        QCOMPARE(status() & 0x02FF, 0x0237);
        QVERIFY(control(0x0002)); // quick stop
        QCOMPARE(status() & 0x006F, 0x0007);
        QVERIFY(control(0x0000));
        QCOMPARE(status(), 0x0050);
        // Without mains, "switch on" is not processed (status bit 4 clear).
        m_acu->motion().setMains(false);
        QVERIFY(control(0x0006));
        QVERIFY(control(0x0007));
        QCOMPARE(status(), 0x0021);
        m_acu->motion().setMains(true);
        // Without positioning control, 0x0000 -> 0x000F enables at once (4').
        QVERIFY(await(m_client->write(30, 5, DataType::Unsigned16, qulonglong(210))).ok());
        QVERIFY(control(0x0000));
        QVERIFY(control(0x000F));
        QCOMPARE(status() & 0x02FF, 0x0237);
    }

    void faultResetNeedsRisingEdge()
    {
        m_acu->raiseFault(0x2714);
        QVERIFY(control(0x0080)); // bit 7 rises
        QCOMPARE(m_acu->fault(), quint16(0));
        QCOMPARE(status(), 0x0050);
        m_acu->raiseFault(0x2714);
        QVERIFY(control(0x0080)); // stays high: no edge, the fault stays
        QCOMPARE(m_acu->fault(), quint16(0x2714));
        QVERIFY(control(0x0000));
        QVERIFY(control(0x0080));
        QCOMPARE(m_acu->fault(), quint16(0));
    }

    void profilePositionHandshake()
    {
        QVERIFY(await(m_client->write(1454, 5, DataType::Integer16, qlonglong(1))).ok());
        QVERIFY(enableOperation());
        QVERIFY(await(m_client->write(1455, 5, DataType::Integer32, qlonglong(4000))).ok());
        QVERIFY(control(0x001F)); // bit 4 rises: set-point taken, bit 12 set
        QVERIFY(status() & 0x1000);
        QVERIFY(control(0x000F)); // bit 4 falls, so does bit 12
        QVERIFY(!(status() & 0x1000));
        QTRY_VERIFY_WITH_TIMEOUT(status() & 0x0400, 5000); // target reached
        QCOMPARE(await(m_client->read(1108, 0)).value().toLongLong(), 4000);
        QVERIFY(await(m_client->write(1455, 5, DataType::Integer32, qlonglong(-1000))).ok());
        QVERIFY(control(0x005F)); // relative
        QVERIFY(control(0x004F));
        QTRY_VERIFY_WITH_TIMEOUT(status() & 0x0400, 5000);
        QCOMPARE(await(m_client->read(1108, 0)).value().toLongLong(), 3000);
        // 7, 8, 9 do not exist with the override.
        QCOMPARE(codeOf(await(m_client->write(1454, 5, DataType::Integer16, qlonglong(7)))), 1u);
        QCOMPARE(m_acu->controlWritesEeprom(), quint64(0));
    }

    void electricalValuesFollowTheSpeed()
    {
        const auto value = [this](quint16 p) {
            return await(m_client->read(p, 0)).value().toLongLong();
        };
        QVERIFY(await(m_client->write(1454, 5, DataType::Integer16, qlonglong(1))).ok());
        QVERIFY(enableOperation());
        QVERIFY(await(m_client->write(1455, 5, DataType::Integer32, qlonglong(10000000))).ok());
        QVERIFY(control(0x001F));
        // At constant speed (the speed read alike before and after the frequency), the stator
        // frequency is speed x pole pairs / 60 and the current is above its no-load part. Two
        // reads can fall in one step of the motion model while it still accelerates, so the
        // frequency is read between them, until the three agree.
        const double polePairs = double(value(373));
        QString last;
        const auto atConstantSpeed = [&] {
            const qlonglong rpm = value(240);
            const double hz = double(value(210)) / 100.0;
            last = QStringLiteral("%1 Hz at %2 rpm").arg(hz).arg(rpm);
            const double expected = double(rpm) * polePairs / 60.0;
            return rpm != 0 && value(240) == rpm
                && std::abs(hz - expected) <= 0.01 * std::abs(expected) + 0.01;
        };
        QTRY_VERIFY2_WITH_TIMEOUT(atConstantSpeed(), qPrintable(last), 10000);
        QVERIFY(value(211) > 12);
        QVERIFY(control(0x0002)); // quick stop: at standstill no frequency and no current
        QTRY_COMPARE_WITH_TIMEOUT(value(211), 0, 10000);
        QCOMPARE(value(210), 0);
    }

    void remoteContacts()
    {
        QVERIFY(await(m_client->write(412, 5, DataType::Unsigned16, qulonglong(2))).ok());
        QVERIFY(control(0x0001)); // S1IND alone: no start
        QCOMPARE(status() & 0x006F, 0x0023);
        QVERIFY(control(0x0003)); // S1IND + S2IND (start clockwise)
        QCOMPARE(status() & 0x006F, 0x0027);
        QCOMPARE(await(m_client->read(250, 0)).value().toLongLong(), 3);
        m_acu->motion().setSto(false);
        QVERIFY(control(0x0003));
        QCOMPARE(status() & 0x006F, 0x0023);
    }

    void rampsStopWhileThePowerStageIsOff()
    {
        bonfiglioli::AcuMotion &motion = m_acu->motion();
        QTRY_VERIFY(!motion.ticking()); // switch on disabled: nothing changes with time
        QVERIFY(await(m_client->write(1454, 5, DataType::Integer16, qlonglong(1))).ok());
        QVERIFY(enableOperation());
        QVERIFY(motion.ticking());
        QVERIFY(await(m_client->write(1455, 5, DataType::Integer32, qlonglong(10000000))).ok());
        QVERIFY(control(0x001F));
        QTRY_VERIFY_WITH_TIMEOUT(motion.velocity() > 0, 5000); // the positioning ramps up
        QVERIFY(control(0x0006)); // ready to switch on: the power stage is off
        QCOMPARE(motion.velocity(), 0.0);
        QTRY_VERIFY(!motion.ticking());
        const double position = motion.position();
        QTest::qWait(50);
        QCOMPARE(motion.position(), position);
    }

    void controlWordToEepromIsCounted()
    {
        const quint64 before = m_acu->eepromWrites();
        QVERIFY(control(0x0006));
        QCOMPARE(m_acu->eepromWrites(), before);
        QVERIFY(await(m_client->write(410, 0, DataType::Unsigned16, qulonglong(0x0007))).ok());
        QCOMPARE(m_acu->eepromWrites(), before + 1);
        QCOMPARE(m_acu->controlWritesEeprom(), quint64(1));
        QCOMPARE(m_acu->controlWritesRam(), quint64(1));
    }

private:
    bool control(quint16 word)
    {
        return await(m_client->write(410, 5, DataType::Unsigned16, qulonglong(word))).ok();
    }
    int status()
    {
        return int(await(m_client->read(411, 0, DataType::Unsigned16)).value().toUInt());
    }
    // 0x0006, 0x0007, 0x000F: "operation enabled".
    bool enableOperation() { return control(0x0006) && control(0x0007) && control(0x000F); }
    std::unique_ptr<SimulatedAcu> m_acu;
    std::unique_ptr<TcpStream> m_stream;
    std::unique_ptr<VabusClient> m_client;
};

QTEST_GUILESS_MAIN(TstSimulatedAcu)
#include "tst_simulatedacu.moc"
