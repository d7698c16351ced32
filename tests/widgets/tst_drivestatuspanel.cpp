#include "devices/bonfiglioli/acudescription.h"
#include "devices/bonfiglioli/acustatussource.h"
#include "fakeconnection.h"
#include "resources/builtindescriptions.h"
#include "textlanguage.h"
#include "widgets/common/lamp.h"
#include "widgets/connection/drivestatuspanel.h"

#include <QLabel>

#include <QSignalSpy>
#include <QTest>
#include <algorithm>

using namespace db;
using db::test::FakeConnection;
using db::widgets::DriveStatusPanel;
using db::widgets::Lamp;

namespace {
constexpr ObjectAddress kStatusword { 0x6041, 0 };
constexpr ObjectAddress kPosition { 0x6064, 0 };

// A MovingCap at standstill in Operation enabled, no faults, no I/O.
void fillHealthyDrive(FakeConnection &fake)
{
    fake.setDictionary(resources::movingCapDictionary());
    fake.setValue(kStatusword, QVariant::fromValue<qulonglong>(0x0427));
    fake.setValue({ 0x6061, 0 }, QVariant::fromValue<qlonglong>(1));
    fake.setValue(kPosition, QVariant::fromValue<qlonglong>(12345));
    fake.setValue({ 0x606C, 0 }, QVariant::fromValue<qlonglong>(0));
    fake.setValue({ 0x6078, 0 }, QVariant::fromValue<qlonglong>(902));
    fake.setValue({ 0x1002, 0 }, QVariant::fromValue<qulonglong>(0));
    fake.setValue({ 0x603F, 0 }, QVariant::fromValue<qulonglong>(0));
    fake.setValue({ 0x60FD, 0 }, QVariant::fromValue<qulonglong>(0));
    fake.setValue({ 0x60FE, 1 }, QVariant::fromValue<qulonglong>(0));
}
// Counts the events of one type a watched object receives.
class EventCounter : public QObject
{
public:
    EventCounter(QObject *watched, QEvent::Type type)
        : m_type(type)
    {
        watched->installEventFilter(this);
    }
    int count = 0;

protected:
    bool eventFilter(QObject *, QEvent *event) override
    {
        if (event->type() == m_type)
            ++count;
        return false;
    }

private:
    QEvent::Type m_type;
};
} // namespace

class TestDriveStatusPanel : public QObject
{
    Q_OBJECT

private:
    QString labelText(const DriveStatusPanel &panel, const char *name)
    {
        auto *label = panel.findChild<QLabel *>(QLatin1String(name));
        return label ? label->text() : QStringLiteral("<no %1>").arg(QLatin1String(name));
    }
    Lamp *lamp(const DriveStatusPanel &panel, const QString &name)
    {
        return panel.findChild<Lamp *>(name);
    }

private Q_SLOTS:
    void operationEnabledIsShownFromStatusword()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        DriveStatusPanel panel;
        panel.setConnection(&fake);
        panel.show();
        fake.open();
        QTRY_COMPARE(labelText(panel, "stateName"), QStringLiteral("Operation enabled"));
        QCOMPARE(labelText(panel, "statusword"), QStringLiteral("0x0427"));
        QCOMPARE(labelText(panel, "mode"), QStringLiteral("Profile position (1)"));
        QCOMPARE(labelText(panel, "position"), QStringLiteral("12345 units"));
        QCOMPARE(labelText(panel, "current"), QStringLiteral("90.2 %"));
        QVERIFY(lamp(panel, QStringLiteral("bit_0400"))->isOn()); // target reached
        QVERIFY(!lamp(panel, QStringLiteral("bit_0008"))->isOn()); // fault
        QVERIFY(!lamp(panel, QStringLiteral("bit_0100"))->isOn()); // moving
        QCOMPARE(labelText(panel, "lastErrorText"), QStringLiteral("No error"));
    }

    // A cycle that brings the same values repaints nothing that changed and lays out nothing:
    // re-setting the badge's style sheet re-polished it and laid out the whole window each time.
    void unchangedCyclesNeitherRestyleNorLayOut()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        QWidget window;
        auto *panel = new DriveStatusPanel(&window);
        panel->setPollInterval(10);
        QSignalSpy cycles(panel, &DriveStatusPanel::cycleFinished);
        panel->setConnection(&fake);
        window.show();
        fake.open();
        QTRY_VERIFY(cycles.count() >= 2);
        QTRY_COMPARE(labelText(*panel, "stateName"), QStringLiteral("Operation enabled"));
        QCoreApplication::processEvents();
        auto *badge = panel->findChild<QLabel *>(QStringLiteral("stateName"));
        QVERIFY(badge);
        const EventCounter restyled(badge, QEvent::StyleChange);
        const EventCounter laidOut(panel, QEvent::LayoutRequest);
        const qsizetype before = cycles.count();
        QTRY_VERIFY(cycles.count() >= before + 5);
        QCoreApplication::processEvents();
        QCOMPARE(restyled.count, 0);
        QCOMPARE(laidOut.count, 0);
    }

    void underVoltageFaultShowsDeviceText()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        fake.setValue(kStatusword, QVariant::fromValue<qulonglong>(0x0008));
        fake.setValue({ 0x603F, 0 }, QVariant::fromValue<qulonglong>(0x3221));
        fake.setValue({ 0x1002, 0 }, QVariant::fromValue<qulonglong>(0x10002));
        DriveStatusPanel panel;
        panel.setConnection(&fake);
        panel.show();
        fake.open();
        QTRY_COMPARE(labelText(panel, "stateName"), QStringLiteral("Fault"));
        QVERIFY(lamp(panel, QStringLiteral("bit_0008"))->isOn());
        QVERIFY2(labelText(panel, "lastErrorText").contains(QStringLiteral("Under-voltage")),
                 qPrintable(labelText(panel, "lastErrorText")));
        QVERIFY(labelText(panel, "lastErrorCode").startsWith(QStringLiteral("0x3221")));
        QVERIFY(labelText(panel, "lastErrorCode").contains(QStringLiteral("ERROR_UNDER_VOLT")));
        QCOMPARE(labelText(panel, "statusRegister"), QStringLiteral("0x00010002"));
        QCOMPARE(labelText(panel, "statusRegisterBits"), QStringLiteral("Error under volt (Uzk)"));
        QCOMPARE(labelText(panel, "statusRegisterWarnings"), QStringLiteral("Warning Sensor"));
    }

    void ioLampsFollowBitsFrom16()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        fake.setValue(
            { 0x60FD, 0 },
            QVariant::fromValue<qulonglong>((1u << 16) | (1u << 19) | (1u << 25) | 0xFFFFu));
        fake.setValue({ 0x60FE, 1 }, QVariant::fromValue<qulonglong>(1u << 17));
        DriveStatusPanel panel;
        panel.setConnection(&fake);
        panel.show();
        fake.open();
        QTRY_VERIFY(lamp(panel, QStringLiteral("IN1"))->isOn());
        QVERIFY(lamp(panel, QStringLiteral("IN4"))->isOn());
        QVERIFY(lamp(panel, QStringLiteral("IN10"))->isOn());
        QVERIFY(!lamp(panel, QStringLiteral("IN2"))->isOn()); // bits 0..15 are not inputs
        QVERIFY(!lamp(panel, QStringLiteral("OUT1"))->isOn());
        QVERIFY(lamp(panel, QStringLiteral("OUT2"))->isOn());
        QVERIFY(!lamp(panel, QStringLiteral("OUT4"))->isOn());

        fake.setValue({ 0x60FD, 0 }, QVariant::fromValue<qulonglong>(0));
        QTRY_VERIFY(!lamp(panel, QStringLiteral("IN1"))->isOn());
    }

    void failedReadKeepsValueGreyedOut()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        DriveStatusPanel panel;
        QSignalSpy cycles(&panel, &DriveStatusPanel::cycleFinished);
        panel.setConnection(&fake);
        panel.show();
        fake.open();
        QTRY_COMPARE(labelText(panel, "position"), QStringLiteral("12345 units"));
        QVERIFY(!panel.isStale(kPosition));

        fake.setFailure(kPosition, Error(Error::Kind::Timeout, QStringLiteral("no answer")));
        QTRY_VERIFY(panel.isStale(kPosition));
        QCOMPARE(labelText(panel, "position"), QStringLiteral("12345 units"));
        QVERIFY(labelText(panel, "pollStatus").contains(QStringLiteral("6064:0")));
        QVERIFY(!panel.isStale(kStatusword));

        fake.clearFailure(kPosition);
        QTRY_VERIFY(!panel.isStale(kPosition));
    }

    void nextCycleWaitsForSlowReplies()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        fake.replyDelayMs = 30;
        DriveStatusPanel panel;
        panel.setPollInterval(10);
        QSignalSpy cycles(&panel, &DriveStatusPanel::cycleFinished);
        panel.setConnection(&fake);
        panel.show();
        fake.open();
        QTRY_VERIFY(cycles.count() >= 3);
        QCOMPARE(fake.maxInFlight, int(DriveStatusPanel::polledObjects().size()));
        QVERIFY(fake.readCount <= (cycles.count() + 1) * DriveStatusPanel::polledObjects().size());
    }

    void stopsWhenHiddenAndResumesWhenShown()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        DriveStatusPanel panel;
        QSignalSpy cycles(&panel, &DriveStatusPanel::cycleFinished);
        panel.setConnection(&fake);
        panel.show();
        fake.open();
        QTRY_VERIFY(cycles.count() >= 1);
        panel.hide();
        QTRY_VERIFY(!panel.isPolling());
        const int reads = fake.readCount;
        panel.show();
        QTRY_VERIFY(fake.readCount > reads);
    }

    void stopsWhenDisconnected()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        fake.replyDelayMs = 5;
        DriveStatusPanel panel;
        panel.setConnection(&fake);
        panel.show();
        fake.open();
        QTRY_COMPARE(labelText(panel, "stateName"), QStringLiteral("Operation enabled"));
        fake.goAway();
        QTRY_VERIFY(!panel.isPolling());
        QVERIFY(panel.isStale(kStatusword));
        QCOMPARE(labelText(panel, "statusword"), QStringLiteral("0x0427")); // kept, greyed
        QVERIFY(labelText(panel, "pollStatus").contains(QStringLiteral("disconnected")));
    }

    void worksWithoutConnection()
    {
        DriveStatusPanel panel;
        panel.show();
        panel.setConnection(nullptr);
        QVERIFY(!panel.isPolling());
        QCOMPARE(labelText(panel, "stateName"), QStringLiteral("No status"));
        {
            FakeConnection fake;
            fillHealthyDrive(fake);
            panel.setConnection(&fake);
            fake.open();
            QTRY_COMPARE(labelText(panel, "stateName"), QStringLiteral("Operation enabled"));
        }
        // The connection is gone: the panel notices through its QPointer.
        QVERIFY(panel.connection() == nullptr);
        panel.setConnection(nullptr);
        QCOMPARE(labelText(panel, "pollStatus"), QStringLiteral("No device selected."));
    }

    // An ACTIVE Cube: the same panel, filled from its family's source (411, 260, 270/274, 388,
    // actual values), addresses written as parameter numbers.
    void activeCubeFaultWarningsAndLinkLoss()
    {
        FakeConnection fake;
        fake.setDictionary(bonfiglioli::acuDictionary());
        fake.setAddressFormat(AddressFormat::parameter());
        const auto u = [](qulonglong v) {
            return QVariant::fromValue(v);
        };
        const auto i = [](qlonglong v) {
            return QVariant::fromValue(v);
        };
        fake.setValue({ 411, 0 }, u(0x0098)); // fault + voltage enabled + warning
        fake.setValue({ 260, 0 }, u(0x2714));
        fake.setValue({ 270, 0 }, u(0x8004));
        fake.setValue({ 274, 0 }, u(0x0020));
        fake.setValue({ 388, 0 }, u(4));
        fake.setValue({ 210, 0 }, i(5000));
        fake.setValue({ 211, 0 }, i(-12));
        fake.setValue({ 213, 0 }, i(15));
        fake.setValue({ 240, 0 }, i(1480));
        fake.setValue({ 228, 0 }, i(5000));
        fake.setValue({ 249, 0 }, u(2));
        fake.setStatusSource(new bonfiglioli::AcuStatusSource(&fake));
        DriveStatusPanel panel;
        panel.setConnection(&fake);
        panel.show();
        fake.open();
        QTRY_COMPARE(labelText(panel, "stateName"), QStringLiteral("Fault"));
        QCOMPARE(labelText(panel, "statusword"), QStringLiteral("0x0098"));
        QCOMPARE(labelText(panel, "lastErrorCode"), QStringLiteral("F2714"));
        QCOMPARE(labelText(panel, "lastErrorText"), QStringLiteral("Communication loss to PLC"));
        QCOMPARE(labelText(panel, "statusRegisterWarnings"),
                 QStringLiteral("Warning long-term Ixt\nFollowing error"));
        QCOMPARE(labelText(panel, "frequency"), QStringLiteral("50.00 Hz"));
        QCOMPARE(labelText(panel, "current"), QStringLiteral("-1.2 A"));
        QCOMPARE(labelText(panel, "speed"), QStringLiteral("1480 rpm"));
        QVERIFY2(labelText(panel, "linkLoss").contains(QStringLiteral("388 = 4")),
                 qPrintable(labelText(panel, "linkLoss")));
        QVERIFY(labelText(panel, "linkLoss").contains(QStringLiteral("stops, then goes to fault")));
        QVERIFY(lamp(panel, QStringLiteral("bit_0008"))->isOn()); // fault
        QVERIFY(lamp(panel, QStringLiteral("bit_0080"))->isOn()); // warning
        QVERIFY(!lamp(panel, QStringLiteral("bit_0400"))->isOn()); // target reached
        QVERIFY(!panel.findChild<QLabel *>(QStringLiteral("position"))); // no CiA 402 rows
        QVERIFY(!lamp(panel, QStringLiteral("IN1"))); // no I/O on this family

        // A failed read names the parameter as the drive's documentation writes it.
        fake.setFailure({ 211, 0 }, Error(Error::Kind::Timeout, QStringLiteral("no answer")));
        QTRY_VERIFY(panel.isStale({ 211, 0 }));
        QVERIFY2(labelText(panel, "pollStatus").contains(QStringLiteral("211:")),
                 qPrintable(labelText(panel, "pollStatus")));
        QCOMPARE(labelText(panel, "current"), QStringLiteral("-1.2 A"));

        // Fault cleared, drive running.
        fake.clearFailure({ 211, 0 });
        fake.setValue({ 411, 0 }, u(0x0637));
        fake.setValue({ 260, 0 }, u(0));
        fake.setValue({ 270, 0 }, u(0));
        fake.setValue({ 274, 0 }, u(0));
        QTRY_COMPARE(labelText(panel, "stateName"), QStringLiteral("Operation enabled"));
        QTRY_COMPARE(labelText(panel, "lastErrorText"), QStringLiteral("No fault"));
        QVERIFY(lamp(panel, QStringLiteral("bit_0400"))->isOn());
    }

    // In German the panel names the actual values, the warning bits and the fault register's bits
    // as the devices' German manuals do.
    void deviceTextsInTheProgramsLanguage()
    {
        const test::TextLanguage german(QStringLiteral("de"));
        FakeConnection acu;
        acu.setDictionary(bonfiglioli::acuDictionary());
        acu.setAddressFormat(AddressFormat::parameter());
        acu.setValue({ 411, 0 }, QVariant::fromValue<qulonglong>(0x0080));
        acu.setValue({ 270, 0 }, QVariant::fromValue<qulonglong>(0x8004));
        acu.setValue({ 274, 0 }, QVariant::fromValue<qulonglong>(0x0020));
        acu.setValue({ 210, 0 }, QVariant::fromValue<qlonglong>(5000));
        acu.setStatusSource(new bonfiglioli::AcuStatusSource(&acu));
        DriveStatusPanel panel;
        panel.setConnection(&acu);
        panel.show();
        acu.open();
        QTRY_COMPARE(labelText(panel, "statusRegisterWarnings"),
                     QStringLiteral("Warnung Langzeit-Ixt\nSchleppfehler"));
        const auto labels = panel.findChildren<QLabel *>();
        QVERIFY(std::any_of(labels.cbegin(), labels.cend(), [](const QLabel *l) {
            return l->text() == QStringLiteral("Ständerfrequenz (210):");
        }));

        FakeConnection movingCap;
        fillHealthyDrive(movingCap);
        movingCap.setValue({ 0x1002, 0 }, QVariant::fromValue<qulonglong>(0x0801));
        DriveStatusPanel capPanel;
        capPanel.setConnection(&movingCap);
        capPanel.show();
        movingCap.open();
        QTRY_COMPARE(labelText(capPanel, "statusRegisterBits"),
                     QStringLiteral("Fehler Überspannung (Uzk)\nFehler Überstrom"));
        QCOMPARE(labelText(capPanel, "position"), QStringLiteral("12345 Einheiten"));
    }

    // Two views of one connection share its source: one poller, one read per object per cycle.
    void viewsShareOnePoller()
    {
        FakeConnection fake;
        fillHealthyDrive(fake);
        DriveStatusPanel first;
        DriveStatusPanel second;
        first.setConnection(&fake);
        second.setConnection(&fake);
        QCOMPARE(first.source(), second.source());
        first.show();
        second.show();
        fake.open();
        QTRY_VERIFY(first.source()->cycles() >= 3);
        const int cycles = first.source()->cycles();
        QVERIFY(fake.readCount <= (cycles + 1) * int(DriveStatusPanel::polledObjects().size()));
        QCOMPARE(labelText(second, "stateName"), QStringLiteral("Operation enabled"));
        first.hide();
        QVERIFY(second.isPolling()); // still held by the other view
        second.hide();
        QTRY_VERIFY(!first.source()->isPolling());
    }
};

QTEST_MAIN(TestDriveStatusPanel)
#include "tst_drivestatuspanel.moc"
