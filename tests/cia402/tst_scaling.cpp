// Level 1: unit scaling (movingcap.md 9.7 worked example) and the power state machine plan.
#include "cia402/drivecontroller.h"
#include "cia402/scaling.h"

#include <QTest>

using namespace db;
using namespace db::cia402;

class TestScaling : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void workedExample()
    {
        // 65536 inc/rev, gear 5:1, feed 100 mm per output revolution (movingcap.md 9.7).
        const QHash<ObjectAddress, QVariant> values {
            { { 0x608F, 1 }, 65536 }, { { 0x608F, 2 }, 1 },   { { 0x6091, 1 }, 5 },
            { { 0x6091, 2 }, 1 },     { { 0x6092, 1 }, 100 }, { { 0x6092, 2 }, 1 },
        };
        auto s = Scaling::fromValues(values);
        QVERIFY(s.ok());
        QCOMPARE(s->toUser(1.0), 0.00030517578125);
        QVERIFY(qAbs(s->toUser(80000) - 24.4140625) < 1e-9); // "~24.41 mm"
        QCOMPARE(s->toIncrements(s->toUser(80000)), 80000.0);
    }
    void missingDivisorIsAnError()
    {
        QHash<ObjectAddress, QVariant> values;
        for (const auto &a : Scaling::objects())
            values.insert(a, 1);
        values.insert({ 0x6092, 2 }, 0);
        QVERIFY(!Scaling::fromValues(values).ok());
    }
    void rotaryAcceleration()
    {
        // Simulator settings: gear 1:1, feed 360 units (degrees) per revolution.
        Scaling s;
        s.feed = 360;
        QCOMPARE(s.rotaryAccelerationToUser(1000), 10000.0); // 1000 x 100/3600 rev/s^2 x 360
        QCOMPARE(s.rotaryAccelerationToRaw(10000), 1000.0);
    }
    void plan_data()
    {
        QTest::addColumn<int>("from");
        QTest::addColumn<int>("to");
        QTest::addColumn<QList<int>>("controlwords");
        using S = State;
        QTest::newRow("SOD->OE") << int(S::SwitchOnDisabled) << int(S::OperationEnabled)
                                 << QList<int> { 0x06, 0x07, 0x0F };
        QTest::newRow("fault->OE") << int(S::Fault) << int(S::OperationEnabled)
                                   << QList<int> { 0x00, 0x80, 0x06, 0x07, 0x0F };
        QTest::newRow("QSA->OE") << int(S::QuickStopActive) << int(S::OperationEnabled)
                                 << QList<int> { 0x00, 0x06, 0x07, 0x0F };
        QTest::newRow("OE->SOD") << int(S::OperationEnabled) << int(S::SwitchOnDisabled)
                                 << QList<int> { 0x00 };
        QTest::newRow("OE->SO") << int(S::OperationEnabled) << int(S::SwitchedOn)
                                << QList<int> { 0x07 };
        QTest::newRow("OE->RTSO") << int(S::OperationEnabled) << int(S::ReadyToSwitchOn)
                                  << QList<int> { 0x06 };
        QTest::newRow("SOD->SO") << int(S::SwitchOnDisabled) << int(S::SwitchedOn)
                                 << QList<int> { 0x06, 0x07 };
        QTest::newRow("same") << int(S::SwitchedOn) << int(S::SwitchedOn) << QList<int> {};
    }
    void plan()
    {
        QFETCH(int, from);
        QFETCH(int, to);
        QFETCH(QList<int>, controlwords);
        QList<int> got;
        for (const auto &step : DriveController::plan(State(from), State(to)))
            got.append(step.controlword);
        QCOMPARE(got, controlwords);
    }
};

QTEST_GUILESS_MAIN(TestScaling)
#include "tst_scaling.moc"
