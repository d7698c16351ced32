// Level 1: the axis configuration from a CiA 402 drive's limit objects, here the rotary settings
// of the position option code 60F2h (movingcap.md 6.2) with 607Dh as the rotary range.
#include "motion/axislimits.h"

#include <QTest>

using namespace db;
using namespace db::motion;

class TestAxisLimits : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void positionOptionCode_data()
    {
        QTest::addColumn<int>("option");
        QTest::addColumn<bool>("endless");
        QTest::addColumn<double>("cycle");
        QTest::addColumn<int>("permitted");
        QTest::addColumn<bool>("softLimits");
        using P = PermittedDirection;
        QTest::newRow("linear, relative to last target")
            << 0x00 << false << 360.0 << int(P::Both) << true;
        QTest::newRow("linear, relative to actual")
            << 0x02 << false << 360.0 << int(P::Both) << true;
        QTest::newRow("rotary, negative only")
            << 0x40 << true << 7200.0 << int(P::NegativeOnly) << false;
        QTest::newRow("rotary, positive only")
            << 0x81 << true << 7200.0 << int(P::PositiveOnly) << false;
        QTest::newRow("rotary, shortest way") << 0xC0 << true << 7200.0 << int(P::Both) << false;
    }
    void positionOptionCode()
    {
        QFETCH(int, option);
        QFETCH(bool, endless);
        QFETCH(double, cycle);
        QFETCH(int, permitted);
        QFETCH(bool, softLimits);
        ObjectDictionary dictionary;
        const QHash<ObjectAddress, QVariant> values {
            { ObjectAddress(0x607D, 1), 800 },
            { ObjectAddress(0x607D, 2), 8000 },
            { ObjectAddress(0x60F2, 0), option },
        };
        const AxisConfig c = axislimits::fromValues(values, dictionary, {}, false);
        QCOMPARE(c.endless, endless);
        QCOMPARE(c.cycleLength, cycle);
        QCOMPARE(int(c.permitted), permitted);
        QCOMPARE(c.softLimitsUsed, softLimits);
    }

    void rotaryWithoutRangeKeepsTheDefaultCycle()
    {
        const AxisConfig c = axislimits::fromValues({ { ObjectAddress(0x60F2, 0), 0xC0 } },
                                                    ObjectDictionary(), {}, false);
        QVERIFY(c.endless);
        QCOMPARE(c.cycleLength, AxisConfig().cycleLength);
    }

    void readsThePositionOptionCodeWhenDescribed()
    {
        ObjectDictionary dictionary;
        ObjectDef def;
        def.address = ObjectAddress(0x60F2, 0);
        def.type = DataType::Unsigned16;
        dictionary.insert(def);
        QVERIFY(axislimits::objects(dictionary).contains(ObjectAddress(0x60F2, 0)));
    }
};

QTEST_GUILESS_MAIN(TestAxisLimits)
#include "tst_axislimits.moc"
