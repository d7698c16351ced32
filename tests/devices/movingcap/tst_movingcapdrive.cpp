#include "devices/movingcap/movingcapdrive.h"
#include "resources/builtindescriptions.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;
using namespace db::sim;

namespace {
QVariant u(qulonglong v)
{
    return QVariant::fromValue<qulonglong>(v);
}
QVariant s(qlonglong v)
{
    return QVariant::fromValue<qlonglong>(v);
}
} // namespace

class TestMovingCapDrive : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void unknownObjectIsRefused();
    void readOnlyObjectIsRefused();
    void writeOnlyObjectCannotBeRead();
    void outOfRangeValueIsRefused();
    void writesAreVisibleToLaterReads();
    void simulatorDefaultsAreSet();
    void controlwordDrivesStatusword();
    void profilePositionHandshakeMovesAndAcknowledges();
    void computedObjectsFollowTheAxis();
    void velocityModeFromObjects();
    void storeKeepsValuesOverPowerCycleAndUnsavedAreLost();
    void wrongMagicValuesAreRefused();
    void factoryResetRestoresDefaultsButKeeps3300h();
    void faultInjectionSetsObjectsAndEmitsEmcyBytes_data();
    void faultInjectionSetsObjectsAndEmitsEmcyBytes();
    void errorHistoryIsNewestFirstAndFaultResetClearsBits();
    void warningSetsBit7WithoutFault();
    void motionIsRefusedInFaultState();
    void softwareEnableMissingRaisesFff2AtEverySwitchOnAttempt();
    void inputsArePhysicalOrVirtual();
    void captureAndCounterFunctionsUseEdges();
    void timedMotionAbsoluteRunsAfterDelay();
    void inputFunctionCommandRunsFunctionWithInputParameters();
    void jogInputIsHoldToRun();
    void quickStopInputSetsOption6();
    void teachTargetStoresPosition();
    void outputFunctions();
    void tpsrAndTsFollowState();
    void stopMotionStaysInQuickStopAndContinueResumes();
    void timedJogBrakesAfterTime();
    void referenceMethods();
    void goWayIsRelativeToLastTarget();
    void repeatReverseOscillates();
    void statusChangedIsEmitted();
    void realTimeRestsWhileNothingChanges();
};

void TestMovingCapDrive::unknownObjectIsRefused()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    const auto r = drive.read({ 0x1234, 0 });
    QVERIFY(!r);
    QCOMPARE(r.error().message(), QStringLiteral("object 1234:0 does not exist"));
    QCOMPARE(drive.write({ 0x1234, 0 }, s(1)).error().message(),
             QStringLiteral("object 1234:0 does not exist"));
}

void TestMovingCapDrive::readOnlyObjectIsRefused()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    const auto r = drive.write({ 0x6041, 0 }, u(0));
    QCOMPARE(r.error().kind(), Error::Kind::AccessDenied);
    QCOMPARE(r.error().message(), QStringLiteral("6041:0 is read-only"));
}

void TestMovingCapDrive::writeOnlyObjectCannotBeRead()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QCOMPARE(drive.read({ 0x1010, 1 }).error().kind(), Error::Kind::AccessDenied);
}

void TestMovingCapDrive::outOfRangeValueIsRefused()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QCOMPARE(drive.write({ 0x6083, 0 }, u(20001)).error().kind(), Error::Kind::OutOfRange);
    QCOMPARE(drive.write({ 0x6040, 0 }, s(-1)).error().kind(), Error::Kind::OutOfRange);
    QCOMPARE(drive.read({ 0x6083, 0 }).value().toULongLong(), 1000ull);
}

void TestMovingCapDrive::writesAreVisibleToLaterReads()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QVERIFY(drive.write({ 0x3511, 8 }, s(120)));
    QCOMPARE(drive.read({ 0x3511, 8 }).value().toLongLong(), 120);
    QCOMPARE(drive.read({ 0x3511, 8 }).value().typeId(), QMetaType::LongLong);
}

void TestMovingCapDrive::simulatorDefaultsAreSet()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QCOMPARE(drive.read({ 0x6092, 1 }).value().toULongLong(), 360ull);
    QCOMPARE(drive.read({ 0x6081, 0 }).value().toULongLong(), 720ull);
    QCOMPARE(drive.read({ 0x6075, 0 }).value().toULongLong(), 2500ull);
    QCOMPARE(drive.read({ 0x6067, 0 }).value().toULongLong(), 5000ull); // description default
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), 0x0040ull);
    MovingCapOptions fixture;
    fixture.initialValues.insert({ 0x3511, 8 }, 110);
    MovingCapDrive docklight(resources::movingCapDictionary(), fixture);
    QCOMPARE(docklight.read({ 0x3511, 8 }).value().toLongLong(), 110);
}

void TestMovingCapDrive::controlwordDrivesStatusword()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    for (auto [cw, expected] : QList<QPair<int, int>> {
             { 6, 0x0021 }, { 7, 0x0023 }, { 15, 0x0427 }, { 7, 0x0023 }, { 0, 0x0040 } }) {
        QVERIFY(drive.write({ 0x6040, 0 }, u(cw)));
        QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), qulonglong(expected));
    }
}

void TestMovingCapDrive::profilePositionHandshakeMovesAndAcknowledges()
{
    // Spec 9.2 example sequence.
    MovingCapDrive drive(resources::movingCapDictionary());
    for (int cw : { 6, 7, 15 })
        drive.write({ 0x6040, 0 }, u(cw));
    drive.write({ 0x6081, 0 }, u(1000));
    drive.write({ 0x607A, 0 }, s(3000));
    drive.write({ 0x6040, 0 }, u(31));
    quint16 word = drive.statusword();
    QVERIFY(word & 0x1000); // set-point acknowledged
    drive.advance(0.5);
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), 0x1127ull);
    drive.write({ 0x6040, 0 }, u(15));
    QVERIFY(!(drive.statusword() & 0x1000));
    drive.advance(5.0);
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), 0x0427ull);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 3000);
}

void TestMovingCapDrive::computedObjectsFollowTheAxis()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x6081, 0 }, u(100));
    QVERIFY(drive.go(720));
    QCOMPARE(drive.read({ 0x6061, 0 }).value().toLongLong(), 1);
    drive.advance(2.0);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), 100);
    const qint64 position = drive.read({ 0x6064, 0 }).value().toLongLong();
    QVERIFY(position > 150 && position < 200);
    // 60FCh in increments: 65536 per 360 degrees.
    const double demand = drive.axis().demandPosition();
    QCOMPARE(drive.read({ 0x60FC, 0 }).value().toLongLong(), qRound64(demand * 65536 / 360));
    const qint64 current = drive.read({ 0x6078, 0 }).value().toLongLong();
    QVERIFY(current > 30 && current < 50); // friction while cruising
    QCOMPARE(drive.read({ 0x3401, 0x0A }).value().toULongLong(), 35ull);
    QCOMPARE(drive.read({ 0x1001, 0 }).value().toULongLong(), 0ull);
}

void TestMovingCapDrive::velocityModeFromObjects()
{
    // Spec 9.3 example.
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x6060, 0 }, s(3));
    drive.write({ 0x60FF, 0 }, s(100));
    for (int cw : { 6, 7, 15 })
        drive.write({ 0x6040, 0 }, u(cw));
    drive.advance(1.0);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), 100);
    drive.write({ 0x60FF, 0 }, s(0));
    drive.advance(1.0);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), 0);
}

void TestMovingCapDrive::storeKeepsValuesOverPowerCycleAndUnsavedAreLost()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x6067, 0 }, u(100));
    QVERIFY(drive.write({ 0x1010, 1 }, u(1702257011)));
    drive.write({ 0x6067, 0 }, u(200));
    drive.write({ 0x340F, 1 }, u(4242));
    drive.powerCycle();
    QCOMPARE(drive.read({ 0x6067, 0 }).value().toULongLong(), 100ull);
    QCOMPARE(drive.read({ 0x340F, 1 }).value().toULongLong(), 0ull);
}

void TestMovingCapDrive::wrongMagicValuesAreRefused()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    const auto save = drive.write({ 0x1010, 1 }, u(1));
    QVERIFY(!save);
    QVERIFY(save.error().message().contains(QLatin1String("save")));
    QVERIFY(!drive.write({ 0x1011, 1 }, u(1702257011)));
}

void TestMovingCapDrive::factoryResetRestoresDefaultsButKeeps3300h()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x6067, 0 }, u(100));
    drive.write({ 0x3301, 4 }, u(500));
    drive.write({ 0x3300, 4 }, u(20));
    drive.write({ 0x1010, 1 }, u(1702257011));
    QVERIFY(drive.write({ 0x1011, 1 }, u(1684107116)));
    QCOMPARE(drive.read({ 0x6067, 0 }).value().toULongLong(), 5000ull);
    QCOMPARE(drive.read({ 0x3301, 4 }).value().toULongLong(), 0ull);
    QCOMPARE(drive.read({ 0x3300, 4 }).value().toULongLong(), 20ull);
    drive.powerCycle(); // the NVM was reset too
    QCOMPARE(drive.read({ 0x6067, 0 }).value().toULongLong(), 5000ull);
}

void TestMovingCapDrive::faultInjectionSetsObjectsAndEmitsEmcyBytes_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("bit");
    QTest::newRow("2220h") << 0x2220 << QByteArray::fromHex("2022050000000000") << 11;
    QTest::newRow("3211h") << 0x3211 << QByteArray::fromHex("1132050000000000") << 0;
    QTest::newRow("3221h") << 0x3221 << QByteArray::fromHex("2132050000000000") << 1;
    QTest::newRow("4210h") << 0x4210 << QByteArray::fromHex("1042090000000000") << 3;
    QTest::newRow("4220h") << 0x4220 << QByteArray::fromHex("2042050000000000") << 4;
    QTest::newRow("5200h") << 0x5200 << QByteArray::fromHex("0052090000000000") << 2;
    QTest::newRow("7121h") << 0x7121 << QByteArray::fromHex("2171100000000000") << 6;
    QTest::newRow("7510h") << 0x7510 << QByteArray::fromHex("1075100000000000") << 7;
    QTest::newRow("FFF1h") << 0xFFF1 << QByteArray::fromHex("F1FF100000000000") << 8;
    QTest::newRow("FFF2h") << 0xFFF2 << QByteArray::fromHex("F2FF100000000000") << 9;
    QTest::newRow("FFF4h") << 0xFFF4 << QByteArray::fromHex("F4FF100000000000") << 12;
    QTest::newRow("FFF5h") << 0xFFF5 << QByteArray::fromHex("F5FF100000000000") << 13;
}

void TestMovingCapDrive::faultInjectionSetsObjectsAndEmitsEmcyBytes()
{
    QFETCH(int, code);
    QFETCH(QByteArray, bytes);
    QFETCH(int, bit);
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.powerContinue();
    QSignalSpy emcy(&drive, &MovingCapDrive::emergency);
    drive.injectFault(quint16(code));
    QCOMPARE(emcy.size(), 1);
    QCOMPARE(emcy.at(0).at(0).value<quint16>(), quint16(code));
    QCOMPARE(emcy.at(0).at(1).value<quint8>(), quint8(bytes.at(2)));
    QCOMPARE(emcy.at(0).at(2).toByteArray(), bytes);
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), 0x000Full); // fault reaction
    drive.advance(0.1);
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), 0x0008ull);
    QCOMPARE(drive.read({ 0x1002, 0 }).value().toULongLong(), 1ull << bit);
    QCOMPARE(drive.read({ 0x603F, 0 }).value().toULongLong(), qulonglong(code));
    QCOMPARE(drive.read({ 0x1003, 1 }).value().toULongLong(), qulonglong(code));
    QCOMPARE(drive.read({ 0x1001, 0 }).value().toULongLong(), qulonglong(quint8(bytes.at(2))));
    drive.write({ 0x6040, 0 }, u(0x80));
    const quint16 expected = code == 0xFFF5 ? 0x0008 : 0x0040; // FFF5h needs a power cycle
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), qulonglong(expected));
}

void TestMovingCapDrive::errorHistoryIsNewestFirstAndFaultResetClearsBits()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    const QList<quint16> codes { 0x3221, 0x4210, 0x7121, 0x2220, 0xFFF1 };
    for (quint16 code : codes) {
        drive.injectFault(code);
        drive.write({ 0x6040, 0 }, u(0x00));
        drive.write({ 0x6040, 0 }, u(0x80));
    }
    QCOMPARE(drive.read({ 0x1003, 1 }).value().toULongLong(), 0xFFF1ull);
    QCOMPARE(drive.read({ 0x1003, 2 }).value().toULongLong(), 0x2220ull);
    QCOMPARE(drive.read({ 0x1003, 3 }).value().toULongLong(), 0x7121ull);
    QCOMPARE(drive.read({ 0x1003, 4 }).value().toULongLong(), 0x4210ull);
    QCOMPARE(drive.read({ 0x1002, 0 }).value().toULongLong(), 0ull);
    QCOMPARE(drive.read({ 0x603F, 0 }).value().toULongLong(), 0xFFF1ull); // stays listed
    QCOMPARE(drive.state(), cia402::State::SwitchOnDisabled);
}

void TestMovingCapDrive::warningSetsBit7WithoutFault()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.powerContinue();
    drive.setWarnings(0x10000);
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), 0x04A7ull);
    QCOMPARE(drive.read({ 0x1002, 0 }).value().toULongLong(), 0x10000ull);
    QVERIFY(drive.go(90)); // motion still executed
    drive.advance(1.0);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 90);
}

void TestMovingCapDrive::motionIsRefusedInFaultState()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.injectFault(0x3221);
    const auto r = drive.go(100);
    QCOMPARE(r.error().message(), QStringLiteral("drive in fault state"));
    QVERIFY(!drive.jog(1));
    QVERIFY(!drive.reference(35));
    QVERIFY(!drive.powerContinue());
}

void TestMovingCapDrive::softwareEnableMissingRaisesFff2AtEverySwitchOnAttempt()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QSignalSpy emcy(&drive, &MovingCapDrive::emergency);
    drive.write({ 0x3512, 1 }, u(0x0900)); // IN2 = software enable, active high
    drive.write({ 0x6040, 0 }, u(6));
    drive.write({ 0x6040, 0 }, u(7));
    QCOMPARE(drive.state(), cia402::State::Fault);
    QCOMPARE(drive.read({ 0x603F, 0 }).value().toULongLong(), 0xFFF2ull);
    QCOMPARE(drive.read({ 0x1002, 0 }).value().toULongLong(), 0x200ull);
    drive.write({ 0x6040, 0 }, u(0x80));
    QVERIFY(!drive.go(10)); // the automatic switch-on is an attempt too
    QCOMPARE(emcy.size(), 2);
    drive.write({ 0x6040, 0 }, u(0x00));
    drive.write({ 0x6040, 0 }, u(0x80));
    drive.setPhysicalInput(2, true);
    QVERIFY(drive.go(10));
    QCOMPARE(drive.state(), cia402::State::OperationEnabled);
}

void TestMovingCapDrive::inputsArePhysicalOrVirtual()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.setPhysicalInput(1, true);
    drive.write({ 0x3510, 1 }, u(0x40000));
    QCOMPARE(drive.read({ 0x60FD, 0 }).value().toULongLong(), 0x50000ull);
    QCOMPARE(drive.input(3).value(), true);
    QCOMPARE(drive.input(2).value(), false);
    QVERIFY(!drive.input(11));
    drive.write({ 0x3510, 1 }, u(0));
    QCOMPARE(drive.read({ 0x60FD, 0 }).value().toULongLong(), 0x10000ull);
}

void TestMovingCapDrive::captureAndCounterFunctionsUseEdges()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x3513, 1 }, u(0x0102)); // IN3: rising -> Result 1, falling -> Result 2
    drive.write({ 0x3511, 1 }, u(0x0303)); // IN1: count both edges
    drive.go(90);
    drive.advance(1.0);
    drive.setPhysicalInput(3, true);
    drive.go(180);
    drive.advance(1.0);
    drive.setPhysicalInput(3, false);
    QCOMPARE(drive.read({ 0x3513, 3 }).value().toLongLong(), 90);
    QCOMPARE(drive.read({ 0x3513, 4 }).value().toLongLong(), 180);
    drive.write({ 0x3511, 3 }, s(10));
    drive.setPhysicalInput(1, true);
    drive.setPhysicalInput(1, false);
    drive.write({ 0x3510, 1 }, u(0x10000)); // virtual edge counts too
    QCOMPARE(drive.read({ 0x3511, 3 }).value().toLongLong(), 13);
}

void TestMovingCapDrive::timedMotionAbsoluteRunsAfterDelay()
{
    // Spec 8.3 function 4 example.
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x3511, 1 }, u(1024));
    drive.write({ 0x3511, 5 }, s(1000));
    drive.write({ 0x3511, 8 }, s(6300));
    drive.write({ 0x3511, 6 }, s(500));
    drive.write({ 0x3511, 7 }, s(400));
    drive.write({ 0x3511, 9 }, s(200));
    drive.setPhysicalInput(1, true);
    drive.advance(0.9);
    QCOMPARE(drive.state(), cia402::State::SwitchOnDisabled);
    drive.advance(0.2);
    QCOMPARE(drive.state(), cia402::State::OperationEnabled);
    drive.advance(20.0);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 6300);
    QCOMPARE(drive.read({ 0x3511, 4 }).value().toLongLong(), 1);
    QCOMPARE(drive.read({ 0x3511, 3 }).value().toLongLong(), qRound64(6300.0 * 65536 / 360));
}

void TestMovingCapDrive::inputFunctionCommandRunsFunctionWithInputParameters()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x3513, 8 }, s(45));
    QVERIFY(drive.write({ 0x3510, 2 }, u(772))); // 0304h
    drive.advance(2.0);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 45);
    QVERIFY(!drive.write({ 0x3510, 2 }, u(0x0B04)));
}

void TestMovingCapDrive::jogInputIsHoldToRun()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x3514, 1 }, u(0x0B0B));
    drive.write({ 0x3514, 6 }, s(100));
    drive.write({ 0x3514, 7 }, s(100));
    drive.write({ 0x3514, 9 }, s(50));
    drive.write({ 0x3510, 1 }, u(0x80000));
    QCOMPARE(drive.read({ 0x6061, 0 }).value().toLongLong(), 3);
    QCOMPARE(drive.read({ 0x60FF, 0 }).value().toLongLong(), -100);
    drive.advance(1.0);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), -100);
    drive.write({ 0x3510, 1 }, u(0));
    QCOMPARE(drive.read({ 0x60FF, 0 }).value().toLongLong(), 0);
    drive.advance(0.1); // 50 -> 500 deg/s^2: 100 deg/s take 0.2 s
    QVERIFY(drive.axis().velocity() < -30);
    drive.advance(0.3);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), 0);
    QCOMPARE(drive.state(), cia402::State::OperationEnabled); // not a quick stop
}

void TestMovingCapDrive::quickStopInputSetsOption6()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x3515, 1 }, u(0x0500));
    drive.go(3600);
    drive.advance(1.0);
    drive.setPhysicalInput(5, true);
    QCOMPARE(drive.read({ 0x605A, 0 }).value().toLongLong(), 6);
    drive.advance(1.0);
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), 0x0007ull);
}

void TestMovingCapDrive::teachTargetStoresPosition()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x3511, 1 }, u(0x0800));
    drive.write({ 0x3512, 1 }, u(0x0400));
    drive.go(77);
    drive.advance(1.0);
    drive.setPhysicalInput(1, true);
    drive.setPhysicalInput(2, true);
    QCOMPARE(drive.read({ 0x3512, 8 }).value().toLongLong(), 77);
    drive.advance(1.0);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 77); // no move started
}

void TestMovingCapDrive::outputFunctions()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.write({ 0x3611, 1 }, u(1));
    drive.write({ 0x3611, 2 }, s(0x0400)); // OUT1: target reached
    drive.write({ 0x3612, 1 }, u(5)); // OUT2: no fault or warning
    drive.write({ 0x3613, 1 }, u(2));
    drive.write({ 0x3613, 2 }, s(0x0002)); // OUT3: under-voltage bit
    QVERIFY(drive.setOutput(4, true));
    drive.powerContinue();
    drive.advance(0.2);
    QCOMPARE(drive.read({ 0x60FE, 1 }).value().toULongLong(), 0xB0000ull);
    drive.injectFault(0x3221);
    drive.advance(0.1);
    QCOMPARE(drive.read({ 0x60FE, 1 }).value().toULongLong(), 0xC0000ull);
    QVERIFY(drive.write({ 0x60FE, 1 }, u(0)));
    QCOMPARE(drive.read({ 0x60FE, 1 }).value().toULongLong(), 0x40000ull);
    QVERIFY(!drive.setOutput(5, true));
}

void TestMovingCapDrive::tpsrAndTsFollowState()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QCOMPARE(drive.tpsr(), 0x2u);
    QCOMPARE(drive.ts(), 0);
    drive.powerContinue();
    drive.advance(0.2);
    QCOMPARE(drive.tpsr(), 0x10Au);
    QCOMPARE(drive.ts(), 1);
    drive.go(720);
    drive.advance(0.3);
    QCOMPARE(drive.tpsr(), 0x106u);
    QCOMPARE(drive.ts(), 2);
    drive.injectFault(0x4210);
    QCOMPARE(drive.ts(), 9);
    drive.advance(1.0);
    QCOMPARE(drive.tpsr(), 0x3u);
    QCOMPARE(drive.ts(), 9);
}

void TestMovingCapDrive::stopMotionStaysInQuickStopAndContinueResumes()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.go(3600);
    drive.advance(1.0);
    QVERIFY(drive.stopMotion());
    QCOMPARE(drive.state(), cia402::State::QuickStopActive);
    drive.advance(1.0);
    QCOMPARE(drive.state(), cia402::State::QuickStopActive);
    QVERIFY(!drive.axis().isMoving());
    QCOMPARE(drive.read({ 0x605A, 0 }).value().toLongLong(), 1); // SM leaves 605Ah alone
    QVERIFY(drive.continueMotion());
    QCOMPARE(drive.state(), cia402::State::OperationEnabled);
    drive.advance(10.0);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 3600);
}

void TestMovingCapDrive::timedJogBrakesAfterTime()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QVERIFY(drive.setSpeed(300));
    QVERIFY(drive.jog(-1, 500));
    drive.advance(0.4);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), -300);
    drive.advance(0.5);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), 0);
    QCOMPARE(drive.read({ 0x6061, 0 }).value().toLongLong(), 3);
    QVERIFY(drive.jog(1));
    drive.advance(5.0);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), 300); // untimed: keeps going
}

void TestMovingCapDrive::referenceMethods()
{
    MovingCapOptions options;
    options.hardStopPositive = 100.0;
    MovingCapDrive drive(resources::movingCapDictionary(), options);
    QVERIFY(drive.reference(std::nullopt));
    QCOMPARE(drive.state(), cia402::State::SwitchOnDisabled); // REF alone does nothing
    drive.go(50);
    drive.advance(1.0);
    drive.write({ 0x607C, 0 }, s(10));
    QVERIFY(drive.reference(35));
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 10);
    QCOMPARE(drive.read({ 0x6061, 0 }).value().toLongLong(), 6);
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong(), 0x1427ull); // homing attained
    drive.write({ 0x607C, 0 }, s(-5));
    QVERIFY(drive.reference(-18));
    drive.advance(0.5);
    QVERIFY(drive.ts() == 2);
    drive.advance(3.0);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), -5); // stop was 40 units ahead
    QCOMPARE(drive.read({ 0x6041, 0 }).value().toULongLong() & 0x1400, 0x1400ull);
    QVERIFY(!drive.reference(1));
}

void TestMovingCapDrive::goWayIsRelativeToLastTarget()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.go(100);
    drive.advance(1.0);
    QVERIFY(drive.setWay(-30));
    QVERIFY(drive.goWay());
    drive.advance(1.0);
    QVERIFY(drive.goWay(50));
    drive.advance(1.0);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 120);
    QCOMPARE(drive.read({ 0x607A, 0 }).value().toLongLong(), 120);
}

void TestMovingCapDrive::repeatReverseOscillates()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    drive.go(10);
    drive.advance(1.0);
    // 90 degrees take 0.2 s, plus 0.1 s window time, then 1 s wait at each end.
    drive.setRepeatWait(1000);
    drive.setRepeatWay(90);
    QVERIFY(drive.repeatReverse());
    drive.advance(0.6);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 100);
    drive.advance(1.2);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 10);
    drive.advance(1.2);
    QCOMPARE(drive.read({ 0x6064, 0 }).value().toLongLong(), 100);
    drive.stopMotion();
    drive.advance(2.0);
    QVERIFY(!drive.axis().isMoving());
}

void TestMovingCapDrive::statusChangedIsEmitted()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QSignalSpy spy(&drive, &MovingCapDrive::statusChanged);
    drive.write({ 0x6040, 0 }, u(6));
    QCOMPARE(spy.size(), 1);
    QCOMPARE(spy.at(0).at(0).value<quint16>(), quint16(0x0021));
}

void TestMovingCapDrive::realTimeRestsWhileNothingChanges()
{
    MovingCapDrive drive(resources::movingCapDictionary());
    QVERIFY(drive.setSpeed(300));
    drive.startRealTime(5);
    // Without power and with nothing scheduled the timer stops; the drive's time still runs.
    QTRY_VERIFY(!drive.ticking());
    const double restStart = drive.time();
    QTest::qWait(1000);
    QVERIFY(!drive.ticking());
    QVERIFY2(drive.time() >= restStart + 0.99, qPrintable(QString::number(drive.time())));

    // A timed jog after the rest runs its whole time from its arrival: the rest is taken up
    // before the command (a rest counted into the jog would end it after 0.2 s).
    QVERIFY(drive.jog(1, 700));
    QVERIFY(drive.ticking());
    QTest::qWait(300);
    QCOMPARE(drive.read({ 0x606C, 0 }).value().toLongLong(), 300);
    QTRY_COMPARE_WITH_TIMEOUT(drive.read({ 0x606C, 0 }).value().toLongLong(), 0, 5000);

    // Powered at standstill it keeps its timer (the axis holds its position); without power it
    // rests again.
    QVERIFY(drive.ticking());
    QVERIFY(drive.powerQuit());
    QTRY_VERIFY(!drive.ticking());
}

QTEST_GUILESS_MAIN(TestMovingCapDrive)
#include "tst_movingcapdrive.moc"
