// Level 3: the ACTIVE Cube status source against the simulated ACU over loopback TCP: one block
// telegram per poll cycle, the block defined again after an inverter reset and after every
// reconnect, the state, fault, warnings and actual values as the drive reports them, and no
// EEPROM write from status polling, scope polling or the keep-alive.

#include "core/reply.h"
#include "devices/bonfiglioli/acudescription.h"
#include "devices/bonfiglioli/acustatussource.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "scope/pollingsource.h"
#include "vabus/vabusblock.h"
#include "vabus/vabusclient.h"
#include "vabus/vabusconnection.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QtTest>

#include <algorithm>
#include <memory>

using namespace db;
using db::bonfiglioli::AcuStatusSource;
using db::bonfiglioli::SimulatedAcu;

namespace {

QString textOf(const QList<StatusValue> &values, const QString &key)
{
    for (const StatusValue &v : values) {
        if (v.key == key)
            return v.text;
    }
    return QStringLiteral("<no %1>").arg(key);
}

} // namespace

class TstAcuStatusSource : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init()
    {
        m_acu = std::make_unique<SimulatedAcu>();
        QVERIFY(m_acu->listen(0).ok());
        m_requests.clear();
        connect(&m_acu->server(), &vabus::Server::requestHandled, this,
                [this](const vabus::Telegram &request) {
                    m_requests.append({ request.parameter, request.write });
                });
        m_connection = std::make_unique<vabus::VabusConnection>(
            ConnectionUri::parse(QStringLiteral("vabus://127.0.0.1:%1").arg(m_acu->port()))
                .value());
        m_connection->setDictionary(bonfiglioli::acuDictionary());
        m_source = new AcuStatusSource(m_connection.get());
        m_connection->setStatusSource(m_source);
        m_source->setIntervalMs(20);
        QVERIFY(m_connection->openAndWait(3000).ok());
    }
    void cleanup()
    {
        m_connection.reset();
        m_acu.reset();
    }

    void oneBlockTelegramPerCycle()
    {
        m_source->acquire();
        QTRY_VERIFY(m_source->cycles() >= 5);
        m_source->release();
        QTRY_VERIFY(!m_source->isPolling());
        QVERIFY(m_source->usesBlock());
        QCOMPARE(m_source->blockDefinitions(), 1);
        int definitions = 0;
        int blockReads = 0;
        for (const auto &[parameter, write] : std::as_const(m_requests)) {
            if (parameter == 17 && write)
                ++definitions;
            else if (parameter == 19 && !write)
                ++blockReads;
            else
                QFAIL(qPrintable(QStringLiteral("unexpected telegram for %1").arg(parameter)));
        }
        QCOMPARE(definitions, 1);
        QCOMPARE(blockReads, m_source->cycles());
        QCOMPARE(m_acu->eepromWrites(), quint64(0));

        // What the simulator's preset shows.
        QCOMPARE(m_source->state(), StatusSource::State::SwitchOnDisabled);
        QCOMPARE(m_source->statusWordValue().text, QStringLiteral("0x0050"));
        const QList<StatusValue> values = m_source->actualValues();
        QCOMPARE(textOf(values, QStringLiteral("frequency")), QStringLiteral("108.45 Hz"));
        QCOMPARE(textOf(values, QStringLiteral("current")), QStringLiteral("10.2 A"));
        QCOMPARE(textOf(values, QStringLiteral("power")), QStringLiteral("4.0 kW"));
        QVERIFY(values.first().fresh);
        QCOMPARE(m_source->faultText(), QStringLiteral("No fault"));
        QVERIFY(!m_source->faultActive());
        QVERIFY(m_source->warnings().isEmpty());
        QVERIFY2(m_source->linkLossText().contains(QStringLiteral("F2714"))
                     && m_source->linkLossText().contains(QStringLiteral("388 = 1")),
                 qPrintable(m_source->linkLossText()));
    }

    void faultAndWarningsAsTheDriveReportsThem()
    {
        m_acu->raiseFault(0x2714);
        m_acu->setWarnings(0x0001);
        m_acu->setApplicationWarnings(0x0008);
        m_source->acquire();
        QTRY_VERIFY(m_source->cycles() >= 1);
        QCOMPARE(m_source->state(), StatusSource::State::Fault);
        QCOMPARE(m_source->fault().text, QStringLiteral("F2714"));
        QCOMPARE(m_source->faultText(), QStringLiteral("Communication loss to PLC"));
        QVERIFY(m_source->faultActive());
        // 270 bit 15 only points at 274, whose bit names the warning.
        QCOMPARE(m_source->warnings(),
                 QStringList({ QStringLiteral("Warning Ixt"),
                               QStringLiteral("HW limit switch clockwise") }));
        QVERIFY(m_source->statusWord().value() & 0x0080);
    }

    void blockDefinedAgainAfterResetAndReconnect()
    {
        m_source->acquire();
        QTRY_VERIFY(m_source->cycles() >= 2);
        QCOMPARE(m_source->blockDefinitions(), 1);

        // The inverter restarts behind an open TCP connection: 19 fails once (no definition),
        // the next cycle defines the block again and the values come back.
        m_acu->powerCycle();
        QTRY_COMPARE(m_source->blockDefinitions(), 2);
        const int after = m_source->cycles();
        QTRY_VERIFY(m_source->cycles() >= after + 2);
        QVERIFY(m_source->isFresh({ 411, 0 }));
        QVERIFY(m_source->usesBlock());

        // A new connection defines it again.
        m_connection->close();
        QTRY_VERIFY(!m_connection->isConnected());
        QVERIFY(!m_source->isFresh({ 411, 0 }));
        // The module takes one PLC connection: wait until it has seen the old one go.
        QTRY_VERIFY(!m_acu->server().hasClient());
        QVERIFY(m_connection->openAndWait(3000).ok());
        QTRY_COMPARE(m_source->blockDefinitions(), 3);
        QTRY_VERIFY(m_source->isFresh({ 411, 0 }));
        QCOMPARE(m_acu->eepromWrites(), quint64(0));
    }

    void keepAliveAndPollingNeverWriteEeprom()
    {
        m_connection->client()->setKeepAliveIdleMs(30);
        m_source->acquire();
        QTRY_VERIFY(m_source->cycles() >= 3);
        m_source->release();
        // Idle: only the keep-alive talks now.
        const qsizetype before = m_requests.size();
        QTRY_VERIFY(m_requests.size() >= before + 5);
        QCOMPARE(m_requests.last().first, quint16(411));
        QCOMPARE(m_acu->eepromWrites(), quint64(0));
    }

    // The scope's host polling of actual values (stator frequency, RMS current) only reads.
    void scopePollingNeverWritesEeprom()
    {
        scope::PollingSource polling(m_connection.get());
        QVERIFY(polling.addChannel({ 210, 0 }, 0).ok());
        QVERIFY(polling.addChannel({ 211, 0 }, 0).ok());
        QElapsedTimer timeBase;
        timeBase.start();
        polling.start(timeBase);
        QTRY_VERIFY(polling.deliveredCount() >= 200);
        polling.stop();
        QCOMPARE(polling.failedCount(), qint64(0));
        // As fast as the link allows, the two channels stay in one block telegram each time.
        QVERIFY2(polling.readCount() <= polling.deliveredCount() / 2 + 1,
                 qPrintable(QStringLiteral("%1 telegrams for %2 samples")
                                .arg(polling.readCount())
                                .arg(polling.deliveredCount())));
        QCOMPARE(m_acu->eepromWrites(), quint64(0));
    }

    // The block definition has one owner per connection: a definition written by somebody else
    // (here one of the same answer length, in another order, which decodes without an error)
    // is refused while the block is in use, and the status keeps its right values.
    void foreignDefinitionIsRefusedWhileTheBlockIsInUse()
    {
        m_source->acquire();
        QTRY_VERIFY(m_source->cycles() >= 2);
        QVERIFY(m_source->usesBlock());
        auto *reader = m_connection->blockReader();
        QList<vabus::BlockItem> reversed = reader->items();
        std::reverse(reversed.begin(), reversed.end());
        const QByteArray foreign = vabus::blockDefinition(reversed).value();

        const Result<QVariant> written =
            Reply::wait(m_connection->write({ 17, 0 }, QString::fromLatin1(foreign)));
        QVERIFY(!written.ok());
        QCOMPARE(written.error().kind(), Error::Kind::AccessDenied);
        QVERIFY2(written.error().message().contains(QStringLiteral("block definition (17)")),
                 qPrintable(written.error().message()));
        QVERIFY(!Reply::wait(m_connection->write({ 18, 0 }, QStringLiteral("0000"))).ok());

        const int after = m_source->cycles();
        QTRY_VERIFY(m_source->cycles() >= after + 3);
        QCOMPARE(m_source->state(), StatusSource::State::SwitchOnDisabled);
        const QList<StatusValue> values = m_source->actualValues();
        QCOMPARE(textOf(values, QStringLiteral("frequency")), QStringLiteral("108.45 Hz"));
        QCOMPARE(textOf(values, QStringLiteral("current")), QStringLiteral("10.2 A"));
        QCOMPARE(textOf(values, QStringLiteral("power")), QStringLiteral("4.0 kW"));
        QCOMPARE(m_source->blockDefinitions(), 1);

        // Nobody uses the block: 17 may be written, and the block is defined again before the
        // next block read.
        m_source->release();
        QTRY_VERIFY(!m_source->isPolling());
        reader->leave(m_source);
        QVERIFY(Reply::wait(m_connection->write({ 17, 0 }, QString::fromLatin1(foreign))).ok());
        m_source->acquire();
        QTRY_VERIFY(m_source->cycles() >= after + 6);
        QCOMPARE(m_source->blockDefinitions(), 2);
        QCOMPARE(textOf(m_source->actualValues(), QStringLiteral("frequency")),
                 QStringLiteral("108.45 Hz"));
    }

    // The scope's host polling joins the status source's block: its channels ride in the same
    // block telegram (no read of their own), with their right values, and no sample is lost.
    void scopeChannelsRideInTheStatusBlock()
    {
        m_source->acquire();
        QTRY_VERIFY(m_source->cycles() >= 2);
        scope::PollingSource polling(m_connection.get());
        QVERIFY(polling.addChannel({ 210, 0 }, 20).ok());
        QVERIFY(polling.addChannel({ 372, 2 }, 20).ok());
        QHash<int, QList<double>> samples;
        connect(&polling, &scope::TraceSource::samplesReady, this,
                [&](int channel, const scope::TraceSamples &got) {
                    for (const auto &sample : got)
                        samples[channel].append(sample.raw);
                });
        m_requests.clear();
        QElapsedTimer timeBase;
        timeBase.start();
        polling.start(timeBase);
        QTRY_VERIFY(samples.value(0).size() >= 20 && samples.value(1).size() >= 20);
        polling.stop();

        QCOMPARE(polling.lostCount(), qint64(0));
        QCOMPARE(polling.failedCount(), qint64(0));
        QCOMPARE(polling.readCount(), polling.deliveredCount() / 2);
        for (double v : samples.value(0))
            QCOMPARE(v, 10845.0); // 108.45 Hz
        for (double v : samples.value(1))
            QCOMPARE(v, 1390.0); // 372 data set 2
        // Nothing but the block: one new definition (the status parameters and 372:2), then
        // block reads for the status source and the scope alike.
        int definitions = 0;
        for (const auto &[parameter, write] : std::as_const(m_requests)) {
            QVERIFY2((parameter == 17 && write) || (parameter == 19 && !write),
                     qPrintable(QStringLiteral("unexpected telegram for %1").arg(parameter)));
            definitions += parameter == 17 ? 1 : 0;
        }
        QVERIFY(definitions >= 1 && definitions <= 2);
        QVERIFY(m_source->isFresh({ 411, 0 }));
        QCOMPARE(textOf(m_source->actualValues(), QStringLiteral("current")),
                 QStringLiteral("10.2 A"));
        QCOMPARE(m_acu->eepromWrites(), quint64(0));
    }

    // More objects than the block holds, then an inverter that stops answering: the cycle ends
    // with the block read's "no answer"; the objects read one by one are not each waited for.
    void silentInverterEndsTheCycleAtTheBlock()
    {
        QList<ObjectAddress> extra;
        for (const ObjectDef &def : m_connection->dictionary().objects()) {
            if (def.readable() && !m_source->polledObjects().contains(def.address))
                extra.append(def.address);
            if (extra.size() == 12)
                break;
        }
        QObject holder;
        m_connection->setRequestTimeoutMs(500);
        m_source->acquire(&holder, 20, extra);
        QTRY_VERIFY(m_source->cycles() >= 2);
        QVERIFY(m_source->usesBlock());
        const auto readOneByOne = [&] {
            return std::ranges::any_of(m_requests, [](const auto &request) {
                return !request.second && request.first != 19;
            });
        };
        QVERIFY2(readOneByOne(), "every extra object fits the block: the test needs more");

        // Only the objects read one by one report through requestFinished (the block's
        // exchanges do not): in a silent cycle they are not read at all.
        int timeouts = 0;
        connect(
            m_connection.get(), &DeviceConnection::requestFinished, this,
            [&](ObjectAddress, const Error &e) { timeouts += e.kind() == Error::Kind::Timeout; });
        QList<int> timeoutsAtUpdate;
        connect(m_source, &StatusSource::updated, this, [&] { timeoutsAtUpdate.append(timeouts); });
        m_acu->server().setFailure({ vabus::Server::Failure::Silent });
        QTRY_VERIFY_WITH_TIMEOUT(!m_source->statusWordValue().fresh, 30000);
        const qsizetype start = timeoutsAtUpdate.size();
        QTRY_VERIFY_WITH_TIMEOUT(timeoutsAtUpdate.size() >= start + 2, 30000);
        QCOMPARE(timeoutsAtUpdate.at(start + 1) - timeoutsAtUpdate.at(start), 0);
        const QString cause = m_source->statusWordValue().error;
        QVERIFY2(cause.contains(QLatin1String("no answer")), qPrintable(cause));
        for (const ObjectAddress a : extra)
            QVERIFY(!m_source->isFresh(a));
        m_acu->server().setFailure({});
        QTRY_VERIFY_WITH_TIMEOUT(m_source->statusWordValue().fresh, 10000);
    }

    // The inverter is switched off and on: the link drops, the port refuses connections while
    // it starts, the connection tries again until it is back, and the block is defined anew.
    void reconnectsAfterPowerCycle()
    {
        m_connection->setRetryAfterLoss(5000, 50);
        m_source->acquire();
        QTRY_VERIFY(m_source->cycles() >= 2);
        QSignalSpy states(m_connection.get(), &DeviceConnection::stateChanged);
        m_acu->restart(400);
        QTRY_VERIFY(!m_connection->isConnected());
        QTRY_VERIFY(m_connection->isRetryScheduled() || m_connection->isConnected());
        QTRY_VERIFY_WITH_TIMEOUT(m_connection->isConnected(), 5000);
        // At least one attempt was refused while the module started.
        QVERIFY(
            states.count(QVariantList { QVariant::fromValue(DeviceConnection::State::Connecting) })
            >= 2);
        QTRY_COMPARE(m_source->blockDefinitions(), 2);
        QTRY_VERIFY(m_source->isFresh({ 411, 0 }));
        QVERIFY(!m_connection->isRetryScheduled());
    }

    void noRetryAfterOwnCloseOrFailedFirstOpen()
    {
        m_connection->close();
        QTRY_VERIFY(!m_connection->isConnected());
        QVERIFY(!m_connection->isRetryScheduled());
        m_acu->server().close();
        QVERIFY(!m_connection->openAndWait(2000).ok());
        QVERIFY(!m_connection->isRetryScheduled());
    }

private:
    std::unique_ptr<SimulatedAcu> m_acu;
    std::unique_ptr<vabus::VabusConnection> m_connection;
    AcuStatusSource *m_source = nullptr;
    QList<std::pair<quint16, bool>> m_requests;
};

QTEST_GUILESS_MAIN(TstAcuStatusSource)
#include "tst_acustatussource.moc"
