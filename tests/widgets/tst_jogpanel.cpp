// Level 4: the jog/motion panel offscreen against the in-process simulated MovingCap over
// loopback RefGo (and CANopen for the heartbeat stop), driven with QTest input and asserted on
// the simulator's axis. Every safety stop of the panel has a test here: button release, key
// release (auto-repeat ignored), focus loss, window deactivation, disconnect, link loss,
// heartbeat loss, watchdog expiry and Esc anywhere in the main window.
#include "canopen/canopenconnection.h"
#include "canopen/nodemonitor.h"
#include "common/demodrive.h"
#include "common/protocols.h"
#include "devices/movingcap/movingcapdrive.h"
#include "mainwindow.h"
#include "transport/canbus.h"
#include "widgets/common/lamp.h"
#include "widgets/common/logconsole.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/motion/motionform.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QVBoxLayout>

using namespace db;
using namespace db::widgets;
using motion::AxisState;
using motion::CommandKind;

namespace {
constexpr int kMoveMs = 5000;

struct Bench
{
    std::unique_ptr<app::DemoDrive> demo;
    std::shared_ptr<DeviceConnection> connection;
    std::unique_ptr<QWidget> window;
    JogPanel *panel = nullptr;
    QLineEdit *other = nullptr; // a focus target outside the panel

    ~Bench()
    {
        window.reset();
        if (connection) {
            connection->close();
            [[maybe_unused]] const bool closed =
                QTest::qWaitFor([&] { return !connection->isConnected(); }, 2000);
        }
    }

    const sim::SimulatedAxis &axis() { return demo->drive().axis(); }
    QPushButton *button(const char *name)
    {
        return panel->findChild<QPushButton *>(QLatin1String(name));
    }
};

std::unique_ptr<Bench> makeBench(const QHash<ObjectAddress, QVariant> &initial = {},
                                 bool canopen = false)
{
    auto b = std::make_unique<Bench>();
    b->demo = std::make_unique<app::DemoDrive>(initial);
    if (!(canopen ? b->demo->startSlcan() : b->demo->startRefgo()))
        return nullptr;
    auto created =
        app::protocolRegistry().create(canopen ? b->demo->slcanUri() : b->demo->refgoUri());
    if (!created)
        return nullptr;
    b->connection = created.value();
    b->connection->open();
    if (!QTest::qWaitFor([&] { return b->connection->isConnected(); }, 5000))
        return nullptr;
    b->window = std::make_unique<QWidget>();
    auto *layout = new QVBoxLayout(b->window.get());
    b->panel = new JogPanel(b->window.get());
    b->other = new QLineEdit(b->window.get());
    layout->addWidget(b->panel);
    layout->addWidget(b->other);
    b->panel->setConnection(b->connection.get());
    b->window->show();
    QApplication::setActiveWindow(b->window.get());
    if (!QTest::qWaitForWindowActive(b->window.get())
        || !QTest::qWaitFor([&] { return b->panel->limitsKnown(); }, 5000))
        return nullptr;
    return b;
}

bool enable(Bench &b)
{
    QTest::mouseClick(b.button("enable"), Qt::LeftButton);
    return QTest::qWaitFor(
        [&] {
            return b.panel->motionAxis()->state() == AxisState::Standstill
                && b.demo->drive().state() == cia402::State::OperationEnabled;
        },
        kMoveMs);
}
} // namespace

class TestJogPanel : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_settingsDir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    }

    void enableShowsPoweredLamp()
    {
        auto b = makeBench();
        QVERIFY(b);
        auto *powered = b->panel->findChild<Lamp *>(QStringLiteral("powered"));
        QVERIFY(!powered->isOn());
        QVERIFY(enable(*b));
        QTRY_VERIFY(powered->isOn());
        // A MovingCap needs no homing: referenced from the start.
        QVERIFY(b->panel->findChild<Lamp *>(QStringLiteral("referenced"))->isOn());
        QTest::mouseClick(b->button("disable"), Qt::LeftButton);
        QTRY_COMPARE(b->panel->motionAxis()->state(), AxisState::Disabled);
        QTRY_VERIFY(!powered->isOn());
    }

    void jogButtonHoldThenRelease()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        QTest::mousePress(b->button("jogPlus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().position() > 50, kMoveMs);
        QVERIFY(b->axis().isMoving());
        QCOMPARE(b->panel->jogDirection(), 1);
        QTest::mouseRelease(b->button("jogPlus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
        QVERIFY(b->panel->lastStopReason().contains(QLatin1String("released")));
        // A ramp stop (MC_Halt), not a quick stop: the drive stays enabled.
        QCOMPARE(b->demo->drive().state(), cia402::State::OperationEnabled);
        const double stoppedAt = b->axis().position();
        QTest::mousePress(b->button("jogMinus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().position() < stoppedAt - 50, kMoveMs);
        QTest::mouseRelease(b->button("jogMinus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
    }

    void jogKeysIgnoreAutoRepeat()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        b->panel->setFocus();
        QTest::keyPress(b->panel, Qt::Key_Right);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().position() > 50, kMoveMs);
        // Auto-repeat sends release/press pairs while the key is held: they change nothing.
        QKeyEvent repeatRelease(QEvent::KeyRelease, Qt::Key_Right, Qt::NoModifier, QString(), true);
        QKeyEvent repeatPress(QEvent::KeyPress, Qt::Key_Right, Qt::NoModifier, QString(), true);
        QApplication::sendEvent(b->panel, &repeatRelease);
        QApplication::sendEvent(b->panel, &repeatPress);
        QCOMPARE(b->panel->jogDirection(), 1);
        const double before = b->axis().position();
        QTRY_VERIFY(b->axis().position() > before + 20); // still jogging
        QTest::keyRelease(b->panel, Qt::Key_Right);
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
        QVERIFY(b->panel->lastStopReason().contains(QLatin1String("key released")));
        QTest::keyPress(b->panel, Qt::Key_Minus);
        QCOMPARE(b->panel->jogDirection(), -1);
        QTest::keyRelease(b->panel, Qt::Key_Minus);
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
    }

    void focusLossStopsJog()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        b->panel->setFocus();
        QTRY_VERIFY(b->panel->hasFocus());
        QTest::keyPress(b->panel, Qt::Key_Right);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().isMoving(), kMoveMs);
        b->other->setFocus(); // e.g. a click into another part of the window
        QCOMPARE(b->panel->jogDirection(), 0);
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
        QVERIFY(b->panel->lastStopReason().contains(QLatin1String("focus")));
    }

    void windowDeactivationStopsJog()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        // Jogging by key: a pressed jog button would be released by the focus change first.
        b->panel->setFocus();
        QTest::keyPress(b->panel, Qt::Key_Right);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().isMoving(), kMoveMs);
        QWidget elsewhere;
        elsewhere.show();
        QApplication::setActiveWindow(&elsewhere);
        QVERIFY(QTest::qWaitForWindowActive(&elsewhere));
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
        QVERIFY2(b->panel->lastStopReason().contains(QLatin1String("deactivated"))
                     || b->panel->lastStopReason().contains(QLatin1String("focus")),
                 qPrintable(b->panel->lastStopReason()));
    }

    void watchdogStopsWhenKeepAliveStops()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        QTest::mousePress(b->button("jogPlus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().isMoving(), kMoveMs);
        // The GUI stops refreshing: nobody feeds the deadman any more.
        auto *keepAlive = b->panel->findChild<QTimer *>(QStringLiteral("keepAliveTimer"));
        QVERIFY(keepAlive && keepAlive->isActive());
        keepAlive->stop();
        QSignalSpy expired(b->panel->motionAxis(), &motion::MotionAxis::watchdogExpired);
        QVERIFY(expired.wait(2 * JogPanel::kWatchdogMs + 500));
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
        QVERIFY(b->panel->lastStopReason().contains(QLatin1String("watchdog")));
    }

    void frozenPanelLeaseRunsOut()
    {
        // The GUI freezes mid-jog (no renewal, no keep-alive, no stop): with the watchdog out of
        // the way, only the lease on the drive is left to stop it.
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        b->panel->motionAxis()->setWatchdogTimeout(0);
        QTest::mousePress(b->button("jogPlus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().position() > 3 * JogPanel::kDefaultJogVelocity
                                         * motion::LeasedMove::kLeaseMs / 1000.0,
                                 kMoveMs);
        QVERIFY(b->axis().isMoving());
        auto *keepAlive = b->panel->findChild<QTimer *>(QStringLiteral("keepAliveTimer"));
        keepAlive->stop();
        motion::LeasedMove *lease = b->panel->leasedMove();
        QVERIFY(lease && lease->isRenewing());
        lease->renewTimer()->stop();
        const double target = lease->lastTarget();
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), int(lease->leaseTimeMs()) + 250);
        QVERIFY2(qAbs(b->axis().position() - target) < 2,
                 qPrintable(QStringLiteral("%1 vs %2").arg(b->axis().position()).arg(target)));
        // Its own profile ended the move: no quick stop, still enabled.
        QCOMPARE(b->demo->drive().state(), cia402::State::OperationEnabled);
        QTest::mouseRelease(b->button("jogPlus"), Qt::LeftButton);
    }

    // MC_MoveVelocity from the form moves in leases, like a jog: the GUI freezes, and the drive
    // stops by itself at the last lease's end; Halt from the form ends a running one.
    void formVelocityIsLeased()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        b->panel->motionAxis()->setWatchdogTimeout(0);
        MotionForm *form = b->panel->motionForm();
        form->selectCommand(CommandKind::MoveVelocity);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(-3000);
        form->execute();
        motion::LeasedMove *lease = b->panel->leasedMove();
        QVERIFY(lease->isRenewing());
        QCOMPARE(lease->direction(), -1);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().position() < -3 * 3000 * 0.3, kMoveMs);
        QVERIFY2(form->statusText().contains(QLatin1String("MC_MoveVelocity in leases")),
                 qPrintable(form->statusText()));
        b->panel->findChild<QTimer *>(QStringLiteral("keepAliveTimer"))->stop();
        lease->renewTimer()->stop();
        const double target = lease->lastTarget();
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), int(lease->leaseTimeMs()) + 250);
        QVERIFY2(qAbs(b->axis().position() - target) < 2,
                 qPrintable(QStringLiteral("%1 vs %2").arg(b->axis().position()).arg(target)));

        b->panel->findChild<QTimer *>(QStringLiteral("keepAliveTimer"))->start();
        form->execute();
        QVERIFY(lease->isRenewing());
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().isMoving(), kMoveMs);
        form->halt();
        QVERIFY(!lease->isRenewing());
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
        QCOMPARE(b->demo->drive().state(), cia402::State::OperationEnabled);
    }

    void canopenEnableArmsSupervision()
    {
        auto b = makeBench({}, true);
        QVERIFY(b);
        auto *label = b->panel->findChild<QLabel *>(QStringLiteral("supervision"));
        QVERIFY2(label->text().contains(QLatin1String("On enable: drive stops within 500 ms")),
                 qPrintable(label->text()));
        QVERIFY(enable(*b));
        QTRY_VERIFY2(label->text().contains(QLatin1String("Active: drive stops within 500 ms")),
                     qPrintable(label->text()));
        sim::MovingCapDrive &drive = b->demo->drive();
        QCOMPARE(drive.read({ 0x6007, 0 }).value().toInt(), 3);
        QCOMPARE(drive.read({ 0x100D, 0 }).value().toInt(), 5);
        QTest::mouseClick(b->button("disable"), Qt::LeftButton);
        QTRY_VERIFY(label->text().contains(QLatin1String("On enable:")));
        QCOMPARE(drive.read({ 0x6007, 0 }).value().toInt(), 1);
        QCOMPARE(drive.read({ 0x100D, 0 }).value().toInt(), 0);
        // RefGo has nothing of the kind.
        auto r = makeBench();
        QVERIFY(r);
        QVERIFY(r->panel->findChild<QLabel *>(QStringLiteral("supervision"))
                    ->text()
                    .contains(QLatin1String("No drive-side supervision")));
    }

    void linkLossEndsJogWithTheCause()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        QTest::mousePress(b->button("jogPlus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().isMoving(), kMoveMs);
        b->connection->close();
        QTRY_COMPARE(b->panel->jogDirection(), 0);
        auto *message = b->panel->findChild<QLabel *>(QStringLiteral("message"));
        QTRY_VERIFY2(message->text().contains(QLatin1String("onnection lost")),
                     qPrintable(message->text()));
        QVERIFY(!b->button("jogPlus")->isEnabled());
    }

    void connectionDestroyedWhileJogging()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        QTest::mousePress(b->button("jogPlus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().isMoving(), kMoveMs);
        b->connection.reset(); // the main window removed it: the panel lets go, no crash
        QCOMPARE(b->panel->connection(), nullptr);
        QCOMPARE(b->panel->motionAxis(), nullptr);
        QCOMPARE(b->panel->jogDirection(), 0);
        QVERIFY(!b->button("jogPlus")->isEnabled());
    }

    void heartbeatLossStopsTheAxis()
    {
        auto b = makeBench({}, true);
        QVERIFY(b && enable(*b));
        auto *canopen = qobject_cast<canopen::CanopenConnection *>(b->connection.get());
        QVERIFY(canopen);
        // Guard replies would keep the node alive in the monitor: this test is about the
        // node's own heartbeat, so the panel's node guarding goes off first.
        Reply *disarmed = b->panel->supervision()->disarm();
        QSignalSpy restored(disarmed, &Reply::finished);
        QVERIFY(restored.wait(5000) && disarmed->ok());
        delete disarmed;
        // The node's heartbeat on the bus (0x700 + 50, operational), every 50 ms.
        canopen->monitor()->setConsumerTime(canopen->node(), 250);
        QTimer heartbeat;
        QObject::connect(&heartbeat, &QTimer::timeout, canopen->bus(), [canopen] {
            Q_EMIT canopen->bus()->frameReceived(
                QCanBusFrame(0x700 + canopen->node(), QByteArray(1, '\x05')));
        });
        heartbeat.start(50);
        QTRY_VERIFY(canopen->monitor()->isAlive(canopen->node()));
        QTest::mousePress(b->button("jogPlus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().position() > 50, kMoveMs);
        heartbeat.stop(); // the node falls silent
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
        QVERIFY2(b->panel->lastStopReason().contains(QLatin1String("heartbeat")),
                 qPrintable(b->panel->lastStopReason()));
        QTest::mouseRelease(b->button("jogPlus"), Qt::LeftButton);
    }

    void executeMoveAbsoluteShowsDone()
    {
        auto b = makeBench();
        QVERIFY(b && enable(*b));
        MotionForm *form = b->panel->motionForm();
        form->selectCommand(CommandKind::MoveAbsolute);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("target"))->setValue(1000);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(2000);
        QTest::mouseClick(form->findChild<QPushButton *>(QStringLiteral("execute")),
                          Qt::LeftButton);
        auto *status = form->findChild<QLabel *>(QStringLiteral("commandStatus"));
        QTRY_VERIFY_WITH_TIMEOUT(status->text().contains(QLatin1String("MC_MoveAbsolute: done")),
                                 kMoveMs);
        QVERIFY(qAbs(b->axis().position() - 1000) < 2);
        // MC_MoveAdditive 200 from the last target (S-09).
        form->selectCommand(CommandKind::MoveAdditive);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("target"))->setValue(200);
        form->execute();
        QTRY_VERIFY_WITH_TIMEOUT(status->text().contains(QLatin1String("MC_MoveAdditive: done")),
                                 kMoveMs);
        QVERIFY(qAbs(b->axis().position() - 1200) < 2);
    }

    void refusedCommandShowsTheReason()
    {
        auto b = makeBench();
        QVERIFY(b);
        MotionForm *form = b->panel->motionForm();
        auto *status = form->findChild<QLabel *>(QStringLiteral("commandStatus"));
        form->selectCommand(CommandKind::MoveRelative);
        form->execute(); // not enabled
        QTRY_VERIFY(status->text().contains(QLatin1String("error")));
        QVERIFY2(status->text().contains(QLatin1String("refused: axis not enabled")),
                 qPrintable(status->text()));
        QVERIFY(enable(*b));
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(0);
        form->execute();
        QTRY_VERIFY2(status->text().contains(QLatin1String("is zero")), qPrintable(status->text()));
        QVERIFY(!b->axis().isMoving());
    }

    void limitsAreShownAndRespected()
    {
        auto b =
            makeBench({ { ObjectAddress(0x607D, 1), -3000 }, { ObjectAddress(0x607D, 2), 3000 } });
        QVERIFY(b && enable(*b));
        auto *limits = b->panel->findChild<QLabel *>(QStringLiteral("limits"));
        QVERIFY2(limits->text().contains(QStringLiteral("-3000 … 3000")),
                 qPrintable(limits->text()));
        MotionForm *form = b->panel->motionForm();
        form->selectCommand(CommandKind::MoveAbsolute);
        auto *target = form->findChild<QDoubleSpinBox *>(QStringLiteral("target"));
        target->setValue(9000);
        QCOMPARE(target->value(), 3000.0); // clamped to 607Dh.2
        // A relative step past the limit (a mistyped distance) is refused as input with the rule
        // (R1): nothing starts and the axis stays in Standstill, not ErrorStop.
        form->selectCommand(CommandKind::MoveRelative);
        target->setValue(9000);
        form->execute();
        auto *status = form->findChild<QLabel *>(QStringLiteral("commandStatus"));
        QVERIFY2(status->text().contains(QLatin1String("MC_MoveRelative not started: target "
                                                       "outside the software limit")),
                 qPrintable(status->text()));
        QCOMPARE(b->panel->motionAxis()->state(), AxisState::Standstill);
        QVERIFY(target->hasFocus() || !form->isActiveWindow());
        // Jogging towards the limit stops at it, even while the button is held.
        b->panel->findChild<QDoubleSpinBox *>(QStringLiteral("jogVelocity"))->setValue(5000);
        QTest::mousePress(b->button("jogPlus"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(b->axis().isMoving(), kMoveMs);
        QTRY_VERIFY_WITH_TIMEOUT(!b->axis().isMoving(), kMoveMs);
        QVERIFY2(qAbs(b->axis().position() - 3000) < 2,
                 qPrintable(QString::number(b->axis().position())));
        QTest::mouseRelease(b->button("jogPlus"), Qt::LeftButton);
    }

    // Motion settings belong to a device: a slower drive lowers them and says so, and the first
    // drive gets its own values back.
    void motionSettingsAreKeptPerDevice()
    {
        auto fast = makeBench();
        QVERIFY(fast);
        app::DemoDrive slowDrive;
        QVERIFY(slowDrive.startRefgo());
        auto created = app::protocolRegistry().create(slowDrive.refgoUri());
        QVERIFY(created.ok());
        std::shared_ptr<DeviceConnection> slow = created.value();
        // A drive whose description allows a tenth of the acceleration (6083h at most 30, the
        // axis shows 300 units/s²).
        ObjectDictionary dict = slow->dictionary();
        ObjectDef profileAcceleration = *dict.find(ObjectAddress(0x6083, 0));
        profileAcceleration.maximum = QVariant::fromValue(30ULL);
        dict.insert(profileAcceleration);
        slow->setDictionary(dict);
        slow->open();
        QTRY_VERIFY(slow->isConnected());

        MotionForm *form = fast->panel->motionForm();
        auto *acceleration = form->findChild<QDoubleSpinBox *>(QStringLiteral("acceleration"));
        auto *jogAcceleration =
            fast->panel->findChild<QDoubleSpinBox *>(QStringLiteral("jogAcceleration"));
        acceleration->setValue(50000);
        jogAcceleration->setValue(8000);
        QCOMPARE(acceleration->value(), 50000.0);
        QVERIFY(form->limitNote().isEmpty());

        fast->panel->setConnection(slow.get());
        QTRY_VERIFY_WITH_TIMEOUT(fast->panel->limitsKnown(), kMoveMs);
        QCOMPARE(acceleration->value(), 300.0);
        QCOMPARE(jogAcceleration->value(), 300.0);
        // Not silently: the form and the panel say what was lowered, to what, and why.
        QVERIFY2(form->limitNote().contains(QStringLiteral("Acceleration 20000 → 300"))
                     && form->limitNote().contains(QStringLiteral("maximum")),
                 qPrintable(form->limitNote()));
        QVERIFY(form->findChild<QLabel *>(QStringLiteral("limitNote"))->isVisibleTo(form));
        auto *message = fast->panel->findChild<QLabel *>(QStringLiteral("message"));
        QVERIFY2(message->text().contains(QStringLiteral("Jog acceleration 5000 → 300")),
                 qPrintable(message->text()));
        QVERIFY2(acceleration->toolTip().contains(QStringLiteral("At most 300")),
                 qPrintable(acceleration->toolTip()));

        fast->panel->setConnection(fast->connection.get());
        QTRY_VERIFY_WITH_TIMEOUT(fast->panel->limitsKnown(), kMoveMs);
        QCOMPARE(acceleration->value(), 50000.0); // this drive's own values, not the slow one's
        QCOMPARE(jogAcceleration->value(), 8000.0);
        QVERIFY(form->limitNote().isEmpty());
        fast->panel->setConnection(nullptr);
        slow->close();
    }

    void mainWindowEscStopsFromAnywhere()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo());
        gui::MainWindow window(app::protocolRegistry());
        window.show();
        QApplication::setActiveWindow(&window);
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QVERIFY(window.openConnection(demo.refgoUri()));
        JogPanel *panel = window.jogPanel();
        QVERIFY(panel);
        QTRY_VERIFY_WITH_TIMEOUT(panel->limitsKnown(), 5000);
        panel->enableDrive();
        QTRY_COMPARE_WITH_TIMEOUT(panel->motionAxis()->state(), AxisState::Standstill, 5000);
        MotionForm *form = panel->motionForm();
        form->selectCommand(CommandKind::MoveVelocity);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(800);
        form->execute();
        QTRY_VERIFY_WITH_TIMEOUT(demo.drive().axis().isMoving(), 5000);
        // Esc typed into a widget far from the panel (the log console's filter field, say).
        QWidget *target = window.logConsole();
        target->setFocus();
        QTest::keyClick(target, Qt::Key_Escape);
        QTRY_VERIFY_WITH_TIMEOUT(!demo.drive().axis().isMoving(), 5000);
        QCOMPARE(panel->lastStopReason(), QStringLiteral("Esc"));
        QVERIFY(demo.drive().state() != cia402::State::OperationEnabled); // quick stop
        window.close();
    }

    void mainWindowDisconnectStopsFirst()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo());
        gui::MainWindow window(app::protocolRegistry());
        window.show();
        QVERIFY(window.openConnection(demo.refgoUri()));
        JogPanel *panel = window.jogPanel();
        QTRY_VERIFY_WITH_TIMEOUT(panel->limitsKnown(), 5000);
        panel->enableDrive();
        QTRY_COMPARE_WITH_TIMEOUT(panel->motionAxis()->state(), AxisState::Standstill, 5000);
        panel->startJog(+1);
        QTRY_VERIFY_WITH_TIMEOUT(demo.drive().axis().isMoving(), 5000);
        window.setConfirmation([](const QString &) { return true; }); // "drive enabled: close?"
        window.disconnectCurrent();
        QTRY_COMPARE(window.currentConnection()->state(), DeviceConnection::State::Disconnected);
        // The quick stop went out before the link closed.
        QTRY_VERIFY_WITH_TIMEOUT(!demo.drive().axis().isMoving(), 5000);
        QVERIFY(panel->lastStopReason().contains(QLatin1String("closed by the user")));
        window.close();
    }

    // Not a check: with DRIVEBENCH_SCREENSHOT=FILE.png (under xvfb-run) it saves the main window
    // with the demo drive enabled and mid-move, for docs/screenshot-motion.png.
    void screenshotMidMove()
    {
        const QString file = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT");
        if (file.isEmpty())
            QSKIP("set DRIVEBENCH_SCREENSHOT=FILE.png to save the screenshot");
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo());
        gui::MainWindow window(app::protocolRegistry());
        window.resize(1880, 1040);
        window.show();
        QVERIFY(window.openConnection(demo.refgoUri()));
        JogPanel *panel = window.jogPanel();
        QTRY_VERIFY_WITH_TIMEOUT(panel->limitsKnown(), 5000);
        panel->enableDrive();
        QTRY_COMPARE_WITH_TIMEOUT(panel->motionAxis()->state(), AxisState::Standstill, 5000);
        MotionForm *form = panel->motionForm();
        form->selectCommand(CommandKind::MoveAbsolute);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("target"))->setValue(36000);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(4000);
        form->execute();
        QTRY_VERIFY_WITH_TIMEOUT(demo.drive().axis().position() > 12000, 10000);
        QVERIFY(window.grab().save(file));
        panel->stopAll(QStringLiteral("screenshot taken"));
        window.setConfirmation([](const QString &) { return true; }); // "drive enabled: quit?"
        window.close();
    }
};

QTEST_MAIN(TestJogPanel)
#include "tst_jogpanel.moc"
