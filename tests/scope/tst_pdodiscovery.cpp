// Which TPDO carries which object (scope/pdodiscovery.h), pure level 1: planPdoChannels and
// expectedPeriodMs over hand-made TPDO configurations.
#include "resources/builtindescriptions.h"
#include "scope/pdodiscovery.h"

#include <QtTest>

using namespace db;
using namespace db::scope;
using canopen::PdoConfig;

namespace {
ObjectDictionary testDictionary()
{
    return resources::builtinDescription(QStringLiteral("drivebench_testnode")).valueOr({});
}

PdoConfig tpdo(int number, quint32 cobId, quint8 type, quint16 eventMs,
               QList<canopen::PdoMappingEntry> entries)
{
    PdoConfig c;
    c.direction = canopen::PdoDirection::Transmit;
    c.number = number;
    c.cobId = cobId;
    c.transmissionType = type;
    c.eventTimer = eventMs;
    c.entries = std::move(entries);
    return c;
}
} // namespace

class TstPdoDiscovery : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void expectedPeriods()
    {
        QCOMPARE(expectedPeriodMs(tpdo(0, 0x185, 0xFF, 20, {}), 0), 20);
        QCOMPARE(expectedPeriodMs(tpdo(0, 0x185, 0xFE, 0, {}), 5), 0); // event driven, no timer
        QCOMPARE(expectedPeriodMs(tpdo(0, 0x185, 3, 0, {}), 10), 30); // every 3rd SYNC
        QCOMPARE(expectedPeriodMs(tpdo(0, 0x185, 1, 0, {}), 0), 0); // SYNC period unknown
        QCOMPARE(expectedPeriodMs(tpdo(0, 0x185, 0, 0, {}), 10), 0); // acyclic
    }

    void findsTheTpdoAndBytes()
    {
        const ObjectDictionary dict = testDictionary();
        QVERIFY(!dict.isEmpty());
        const QList<PdoConfig> configs = {
            // disabled: must not be used even though it maps 6064:0 first
            tpdo(0, 0x185 | PdoConfig::kInvalidBit, 0xFF, 10, { { { 0x6064, 0 }, 32 } }),
            // 2100:0 (8 bit) then 6064:0 at byte 1; 2101:0 not on a byte boundary
            tpdo(1, 0x285, 0xFF, 50,
                 { { { 0x2100, 0 }, 8 },
                   { { 0x6064, 0 }, 32 },
                   { { 0x0005, 0 }, 4 },
                   { { 0x2101, 0 }, 16 } }),
            // unknown object: decoded as an unsigned of the mapped size
            tpdo(2, 0x385, 2, 0, { { { 0x2FFF, 1 }, 16 } }),
        };
        const PdoChannelPlan plan = planPdoChannels(
            configs, { { 0x6064, 0 }, { 0x2FFF, 1 }, { 0x2101, 0 }, { 0x2103, 0 } }, dict, 5, 10);
        QCOMPARE(plan.node, 5);
        QCOMPARE(plan.tpdos.size(), 3);
        QCOMPARE(plan.found.size(), 2);
        QCOMPARE(plan.found[0].address, ObjectAddress(0x6064, 0));
        QCOMPARE(plan.found[0].tpdoNumber, 1);
        QCOMPARE(plan.found[0].mapping.cobId, 0x285u);
        QCOMPARE(plan.found[0].mapping.byteOffset, 1);
        QCOMPARE(plan.found[0].mapping.type, DataType::Integer32);
        QCOMPARE(plan.found[0].mapping.expectedPeriodMs, 50);
        QCOMPARE(plan.found[1].mapping.type, DataType::Unsigned16);
        QCOMPARE(plan.found[1].mapping.expectedPeriodMs, 20); // type 2 x SYNC 10 ms
        QCOMPARE(plan.missing,
                 (QList<ObjectAddress> { ObjectAddress(0x2101, 0), ObjectAddress(0x2103, 0) }));
        QVERIFY(!plan.isComplete());
        QCOMPARE(plan.missingText(dict),
                 QStringLiteral("2101:0 Test integer16 is in no TPDO of node 5; 2103:0 Test "
                                "integer32 is in no TPDO of node 5"));

        // The plan's channels go into a PdoSource with names from the dictionary.
        PdoSource source(static_cast<CanBus *>(nullptr));
        const auto added = addPlannedChannels(source, plan, dict, QStringLiteral("dev"));
        QVERIFY(added.ok());
        QCOMPARE(added->size(), 2);
        QCOMPARE(source.channels().at(0).name, QStringLiteral("Position actual value"));
        QCOMPARE(source.mapping(0).cobId, 0x285u);
    }

    void silentPdoCauses()
    {
        using canopen::NmtState;
        PdoChannelPlan plan = planPdoChannels({ tpdo(0, 0x185, 0xFF, 0, { { { 0x6064, 0 }, 32 } }),
                                                tpdo(1, 0x285, 1, 0, { { { 0x2100, 0 }, 8 } }) },
                                              { { 0x6064, 0 }, { 0x2100, 0 } }, {}, 5);
        QCOMPARE(plan.found.size(), 2);
        QCOMPARE(silentPdoCause(plan, NmtState::PreOperational),
                 QStringLiteral("node 5 is pre-operational (heartbeat), not operational: NMT "
                                "start it"));
        QVERIFY(silentPdoCause(plan, NmtState::Stopped).contains(QLatin1String("stopped")));
        QCOMPARE(silentPdoCause(plan, NmtState::Operational),
                 QStringLiteral("node 5 is operational (heartbeat), but TPDO1 has no event timer "
                                "and is sent only on device events; TPDO2 is sent on SYNC "
                                "(transmission type 1) and no SYNC was produced"));
        const QString unknown = silentPdoCause(plan, NmtState::Unknown);
        QVERIFY(unknown.startsWith(QLatin1String("node 5 is probably not operational (no "
                                                 "heartbeat heard): NMT start it; or TPDO1")));
        // A cyclic event-timer PDO has no reason of its own.
        plan = planPdoChannels({ tpdo(0, 0x185, 0xFF, 10, { { { 0x6064, 0 }, 32 } }) },
                               { { 0x6064, 0 } }, {}, 5);
        QCOMPARE(silentPdoCause(plan, NmtState::Unknown),
                 QStringLiteral("node 5 is probably not operational (no heartbeat heard): NMT "
                                "start it"));
    }

    void rpdosAreIgnored()
    {
        PdoConfig rpdo = tpdo(0, 0x205, 0xFF, 0, { { { 0x6064, 0 }, 32 } });
        rpdo.direction = canopen::PdoDirection::Receive;
        const PdoChannelPlan plan = planPdoChannels({ rpdo }, { { 0x6064, 0 } }, {}, 5);
        QVERIFY(plan.found.isEmpty());
        QCOMPARE(plan.missingText({}), QStringLiteral("6064:0 is in no TPDO of node 5"));
    }
};

QTEST_GUILESS_MAIN(TstPdoDiscovery)
#include "tst_pdodiscovery.moc"
