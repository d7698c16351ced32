// The simulated NM17x displays' following error Er 3, direction error Er 6, jump filter,
// dynamic pre-shutdown and scaling: behaviour, status and error bits, display codes.
#include "devices/nm17x/nm17xcodes.h"
#include "nm17xtestline.h"

#include <QElapsedTimer>
#include <QTest>
#include <QTimer>

using namespace db;
using namespace db::nm17x;
using db::test::Line;

namespace {
constexpr quint16 kEr3 = 1u << 2;
constexpr quint16 kEr5 = 1u << 4;
constexpr quint16 kEr6 = 1u << 5;
constexpr double kDefaultScaling = 0.1736111; // 2004h default / 10^7: 1/100 mm per step

// Writes an object as the master would (SDO), and waits until its effect reached the
// application (one queued write per 10 ms cycle).
void write(SimulatedNm17x *d, ObjectAddress address, const QVariant &value)
{
    QVERIFY(d->write(address, value).ok());
    QTest::qWait(3 * SimulatedNm17x::kCycleMs);
}
} // namespace

class TstNm17xDisplayErrors : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void er3WhenTheShaftDoesNotTurn();
    void er6WhenTheMotorTurnsTheWrongWay();
    void dynamicPreShutdownAdaptsTheSwitchOffPoint();
    void jumpFilterDiscardsShortJumps();
    void scalingChangesThePositionOfTheSameSteps();
};

// Driven but the shaft stands: after 2047h:02 the motor stops, Er 3, error bit, 1001h bit 7.
void TstNm17xDisplayErrors::er3WhenTheShaftDoesNotTurn()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    write(d, { 0x2047, 2 }, 5u); // 0.5 s
    d->spindle().setShaftBlocked(true);
    QElapsedTimer clock;
    clock.start();
    line.send(0x37F, "E803000000000300"); // 10.00 mm with release
    QTRY_VERIFY(d->spindle().isMoving());
    QTRY_VERIFY_WITH_TIMEOUT(d->errorWord() & kEr3, 3000);
    QVERIFY2(clock.elapsed() >= 450, qPrintable(QString::number(clock.elapsed())));
    QCOMPARE(d->position(), 0);
    QTRY_VERIFY(!d->spindle().isMoving());
    QCOMPARE(activeErrors(d->errorWord()).at(0).code, QStringLiteral("Er 3"));
    QVERIFY(d->statusWord() & status::Error);
    QVERIFY(!(d->statusWord() & status::InPosition));
    QCOMPARE(d->read({ 0x1001, 0 }).value().toUInt() & 0x80, 0x80u);
    QVERIFY(errorText(d->errorWord()).contains(QLatin1String("shaft does not turn")));

    // Freed, the next command clears Er 3 and reaches its target.
    d->spindle().setShaftBlocked(false);
    line.send(0x37F, "E803000000000300");
    QTRY_VERIFY_WITH_TIMEOUT(d->statusWord() & status::InPosition, 10000);
    QCOMPARE(d->errorWord(), quint16(0));
    QCOMPARE(d->position(), 1000);
}

// The motor turns against its direction signal: the shaft moves the wrong way, and after the
// detection travel the motor stops with Er 6.
void TstNm17xDisplayErrors::er6WhenTheMotorTurnsTheWrongWay()
{
    Line line({ Variant::Nm174 });
    SimulatedNm17x *d = line.devices.at(0);
    line.send(0x000, "017F");
    d->spindle().setWiringReversed(true);
    line.send(0x37F, "E803000000000300"); // 10.00 mm with release: up, but it goes down
    QTRY_VERIFY_WITH_TIMEOUT(d->errorWord() & kEr6, 3000);
    QTRY_VERIFY(!d->spindle().isMoving());
    const double travel = d->spindle().motor().directionErrorTravel;
    QVERIFY2(d->position() < 0 && d->position() >= -travel - 50,
             qPrintable(QString::number(d->position())));
    QCOMPARE(activeErrors(d->errorWord()).at(0).code, QStringLiteral("Er 6"));
    QVERIFY(d->statusWord() & status::Error);
    QVERIFY(errorText(d->errorWord()).contains(QLatin1String("wrong way")));
    // Tippen is stopped the same way.
    line.send(0x37F, "0000000000009100"); // right, medium
    QTRY_VERIFY(d->errorWord() & kEr6);
    QTRY_VERIFY(!d->spindle().isMoving());
    d->spindle().setWiringReversed(false);
    line.send(0x37F, "E803000000000300");
    QTRY_VERIFY_WITH_TIMEOUT(d->statusWord() & status::InPosition, 10000);
    QCOMPARE(d->errorWord(), quint16(0));
}

// The spindle coasts 0.10 mm after the motor stops (25 ms at creep speed). Without dynamic
// pre-shutdown every positioning overshoots (Er 5); with it, half the miss moves the
// switch-off point 2042h:03 after each positioning: 5, 8, 9, 10, and the target is hit.
void TstNm17xDisplayErrors::dynamicPreShutdownAdaptsTheSwitchOffPoint()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    d->spindle().motor().coastMs = 25;
    line.send(0x000, "017F");
    const auto positionTo = [&](const char *frame) {
        line.send(0x37F, frame);
        QTRY_VERIFY(d->spindle().isMoving());
        QTRY_VERIFY_WITH_TIMEOUT(!d->spindle().isMoving(), 10000);
    };
    positionTo("E803000000000300"); // 10.00 mm
    QCOMPARE(d->position(), 1010);
    QVERIFY(d->errorWord() & kEr5);
    QVERIFY(!(d->statusWord() & status::InPosition));
    QCOMPARE(d->read({ 0x2042, 3 }).value().toInt(), 0);

    write(d, { 0x2041, 2 }, 1u);
    const char *targets[] = { "D007000000000300", "B80B000000000300", "A00F000000000300",
                              "8813000000000300", "7017000000000300" };
    const qint32 switchOff[] = { 5, 8, 9, 10, 10 };
    const qint32 reached[] = { 2010, 3005, 4002, 5001, 6000 };
    for (int i = 0; i < 5; ++i) {
        positionTo(targets[i]);
        QCOMPARE(d->position(), reached[i]);
        QCOMPARE(d->read({ 0x2042, 3 }).value().toInt(), switchOff[i]);
    }
    QVERIFY(d->statusWord() & status::InPosition);
    QVERIFY(!(d->errorWord() & kEr5));

    // Off again: the switch-off point stays where it was adapted to.
    write(d, { 0x2041, 2 }, 0u);
    positionTo("581B000000000300"); // 70.00 mm
    QCOMPARE(d->position(), 7000);
    QCOMPARE(d->read({ 0x2042, 3 }).value().toInt(), 10);
}

// Sensor readings off by 1000 steps (2005h:01 = 100 steps): three in a row are discarded
// (2005h:02 = 5), the display never shows them; a lasting jump is taken with the 6th reading;
// with count 1 a longer disturbance shows from its 2nd reading; width 2303 lets it through.
void TstNm17xDisplayErrors::jumpFilterDiscardsShortJumps()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    qint32 lowest = 0;
    qint32 highest = 0;
    QTimer sampler;
    connect(&sampler, &QTimer::timeout, this, [&] {
        lowest = qMin(lowest, d->position());
        highest = qMax(highest, d->position());
    });
    sampler.start(1);
    const qint32 jump = qRound(1000 * kDefaultScaling);

    d->disturbSensor(1000, 3);
    QTRY_VERIFY(!d->sensorDisturbed());
    QTest::qWait(50);
    QCOMPARE(highest, 0);
    QCOMPARE(d->filteredJumps(), 3);

    d->disturbSensor(-1000, 0); // the sensor slipped: taken after 5 discarded readings
    QTRY_COMPARE(d->position(), -jump);
    QCOMPARE(d->filteredJumps(), 8);
    QVERIFY(!d->sensorDisturbed());

    write(d, { 0x2005, 2 }, 1u);
    highest = lowest = d->position();
    d->disturbSensor(1000, 20);
    QTRY_VERIFY(!d->sensorDisturbed());
    QTRY_COMPARE(d->position(), -jump); // back, after one more discarded reading
    QCOMPARE(highest, 0);
    QCOMPARE(d->filteredJumps(), 10);

    write(d, { 0x2005, 1 }, 2303u);
    d->disturbSensor(1000, 0);
    QTRY_COMPARE(d->position(), 0);
    QCOMPARE(d->filteredJumps(), 10);
}

// 2004h is steps x scaling: doubling it (8 mm pitch) doubles the position of the same shaft
// position; the preset offset is added after the scaling.
void TstNm17xDisplayErrors::scalingChangesThePositionOfTheSameSteps()
{
    Line line({ Variant::Nm172 });
    SimulatedNm17x *d = line.devices.at(0);
    d->turnShaft(400); // one revolution of a 4 mm spindle: 2304 steps
    QCOMPARE(d->position(), 400);
    write(d, { 0x2004, 0 }, 3472222u);
    QTRY_COMPARE(d->position(), 800);
    write(d, { 0x6003, 0 }, 1000); // preset: offset 200
    QTRY_COMPARE(d->position(), 1000);
    write(d, { 0x2004, 0 }, 1736111u); // the steps stay, the offset stays: 400 + 200
    QTRY_COMPARE(d->position(), 600);
    QCOMPARE(d->read({ 0x6004, 0 }).value().toInt(), 600);
}

QTEST_MAIN(TstNm17xDisplayErrors)
#include "tst_nm17xdisplayerrors.moc"
