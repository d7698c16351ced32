// Level 4: the Motion dock on an ACTIVE Cube (vabus://) in the main window, against the
// simulated ACU in-process over loopback TCP: enable, a move to its target from the command
// form, the leased jog, the link watchdog (388) shown, the units of the drive, a configuration
// without positioning control, fault reset, and disconnecting while moving stops the axis first.

#include "common/protocols.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "mainwindow.h"
#include "wait.h"
#include "widgets/motion/gearbox.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/motion/motionblockbox.h"
#include "widgets/motion/motionform.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTest>

using namespace db;
using namespace db::widgets;
using db::bonfiglioli::SimulatedAcu;
using motion::AxisState;
using motion::CommandKind;

class TestJogPanelAcu : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init()
    {
        m_acu = std::make_unique<SimulatedAcu>();
        QVERIFY(m_acu->listen(0).ok());
        m_window = std::make_unique<gui::MainWindow>(app::protocolRegistry());
        m_window->resize(1366, 768);
        // "The drive is enabled: close the connection?" is answered yes (no modal dialog).
        m_window->setConfirmation([](const QString &) { return true; });
        m_window->show();
        QVERIFY(m_window->openConnection(QStringLiteral("vabus://127.0.0.1:%1").arg(m_acu->port()))
                    .ok());
        m_panel = m_window->jogPanel();
        DB_TRY_VERIFY_WITH_TIMEOUT(m_panel->limitsKnown(), 5000);
        m_eeprom = m_acu->eepromWrites();
    }
    void cleanup()
    {
        if (m_acu)
            QCOMPARE(m_acu->eepromWrites(), m_eeprom);
        m_window.reset();
        m_acu.reset();
    }

    void enableMoveAndDisable()
    {
        QVERIFY(m_panel->axis());
        m_panel->enableDrive();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_panel->motionAxis()->state(), AxisState::Standstill, 5000);
        QVERIFY(m_acu->isRunning());
        MotionForm *form = m_panel->motionForm();
        form->selectCommand(CommandKind::MoveAbsolute);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("target"))->setValue(30000);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(10000);
        form->execute();
        DB_TRY_VERIFY2_WITH_TIMEOUT(m_acu->motion().position() > 100, qPrintable(allLabels()),
                                    5000);
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->motion().position(), 30000.0, 10000);
        DB_TRY_COMPARE_WITH_TIMEOUT(m_panel->motionAxis()->state(), AxisState::Standstill, 5000);
        // The drive's own units and link supervision are shown.
        const QString texts = allLabels();
        QVERIFY2(texts.contains(QLatin1String("30000.0 u")), qPrintable(texts));
        QVERIFY2(texts.contains(QLatin1String("388 = 1")), qPrintable(texts));
        m_panel->disableDrive();
        DB_TRY_VERIFY_WITH_TIMEOUT(!m_acu->isRunning(), 5000);
        QCOMPARE(m_acu->controlWritesEeprom(), quint64(0));
    }

    void jogRunsInLeasesAndHaltsOnRelease()
    {
        m_panel->enableDrive();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_panel->motionAxis()->state(), AxisState::Standstill, 5000);
        m_panel->startJog(-1);
        DB_TRY_VERIFY_WITH_TIMEOUT(m_acu->motion().position() < -1000, 5000);
        m_panel->stopJog(QStringLiteral("released"));
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->motion().velocity(), 0.0, 3000);
        QVERIFY(m_acu->isRunning()); // halted, still enabled
    }

    void disconnectWhileMovingStopsFirst()
    {
        m_panel->enableDrive();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_panel->motionAxis()->state(), AxisState::Standstill, 5000);
        m_panel->startJog(+1);
        DB_TRY_VERIFY_WITH_TIMEOUT(m_acu->motion().velocity() > 0, 5000);
        m_window->disconnectCurrent();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->motion().velocity(), 0.0, 3000);
        QVERIFY(m_acu->motion().state() != bonfiglioli::AcuMotion::State::OperationEnabled
                || m_acu->motion().velocity() == 0.0);
        QVERIFY(m_panel->lastStopReason().contains(QLatin1String("closed by the user")));
    }

    void motionBlockFromThePanel()
    {
        auto *box = m_panel->findChild<MotionBlockBox *>(QStringLiteral("motionBlocks"));
        QVERIFY(box);
        QVERIFY(box->isVisibleTo(m_panel)); // the ACU has a motion block table
        m_panel->enableDrive();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_panel->motionAxis()->state(), AxisState::Standstill, 5000);
        box->findChild<QSpinBox *>(QStringLiteral("motionBlock"))->setValue(2);
        box->findChild<QPushButton *>(QStringLiteral("runMotionBlock"))->click();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->motion().position(), 5000.0, 10000);
        DB_TRY_VERIFY_WITH_TIMEOUT(!box->isRunning(), 5000);
        QCOMPARE(box->findChild<QLabel *>(QStringLiteral("motionBlockResult"))->text(),
                 QStringLiteral("Block 2 done"));
    }

    // The electronic gear box: shown for an ACU with positioning control, couples at the ratio
    // typed (MC_GearIn, "in gear" from status bit 10) and uncouples (MC_GearOut, to a stop).
    // With DRIVEBENCH_SCREENSHOT_GEAR=FILE.png (under xvfb-run) it also saves the main window at
    // 1366x768 while the axis is in gear.
    void electronicGearFromThePanel()
    {
        auto *box = m_panel->findChild<GearBox *>(QStringLiteral("gearBox"));
        QVERIFY(box);
        QVERIFY(box->isVisibleTo(m_panel));
        m_acu->motion().setMasterSpeed(2000);
        m_panel->enableDrive();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_panel->motionAxis()->state(), AxisState::Standstill, 5000);
        box->findChild<QSpinBox *>(QStringLiteral("gearNumerator"))->setValue(3);
        box->findChild<QSpinBox *>(QStringLiteral("gearDenominator"))->setValue(2);
        box->findChild<QDoubleSpinBox *>(QStringLiteral("gearAcceleration"))->setValue(100000);
        box->findChild<QPushButton *>(QStringLiteral("gearIn"))->click();
        auto *result = box->findChild<QLabel *>(QStringLiteral("gearResult"));
        DB_TRY_VERIFY2_WITH_TIMEOUT(box->isCoupled(), qPrintable(result->text()), 10000);
        QCOMPARE(result->text(), QStringLiteral("In gear at 3:2"));
        QCOMPARE(m_acu->motion().velocity(), 3000.0);
        QCOMPARE(m_panel->motionAxis()->state(), AxisState::SynchronizedMotion);
        const QString file = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_GEAR");
        if (!file.isEmpty()) {
            for (QWidget *w = box->parentWidget(); w; w = w->parentWidget()) {
                if (auto *scroll = qobject_cast<QScrollArea *>(w))
                    scroll->ensureWidgetVisible(box);
            }
            QTest::qWait(300); // a few status rounds: the actual values of the coupled axis
            QVERIFY(m_window->grab().save(file));
        }
        box->findChild<QPushButton *>(QStringLiteral("gearOut"))->click();
        DB_TRY_COMPARE_WITH_TIMEOUT(result->text(), QStringLiteral("Uncoupled, at standstill"),
                                    10000);
        QCOMPARE(m_acu->motion().velocity(), 0.0);
        QCOMPARE(m_panel->motionAxis()->state(), AxisState::Standstill);
    }

    // On a drive without the gear (no positioning control) the box is not offered.
    void noGearBoxWithoutPositioning()
    {
        std::unique_ptr<Reply> r(
            m_window->currentConnection()->write(ObjectAddress(30, 5), qulonglong(210)));
        DB_TRY_VERIFY(r->isFinished());
        QVERIFY(r->ok());
        r.reset();
        m_window.reset(); // a new window on the reconfigured inverter
        DB_TRY_VERIFY(!m_acu->server().hasClient()); // the module takes one PLC connection
        m_window = std::make_unique<gui::MainWindow>(app::protocolRegistry());
        m_window->setConfirmation([](const QString &) { return true; });
        m_window->show();
        const auto reopened =
            m_window->openConnection(QStringLiteral("vabus://127.0.0.1:%1").arg(m_acu->port()));
        QVERIFY2(reopened.ok(), qPrintable(reopened.error().toString()));
        m_panel = m_window->jogPanel();
        DB_TRY_VERIFY_WITH_TIMEOUT(m_panel->limitsKnown(), 5000);
        auto *box = m_panel->findChild<GearBox *>(QStringLiteral("gearBox"));
        QVERIFY(box);
        QVERIFY(!box->isVisibleTo(m_panel));
    }

    void faultResetFromThePanel()
    {
        m_panel->enableDrive();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_panel->motionAxis()->state(), AxisState::Standstill, 5000);
        m_acu->raiseFault(0x2714);
        DB_TRY_VERIFY_WITH_TIMEOUT(m_panel->axis()->status().fault, 5000);
        m_panel->resetFault();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_acu->fault(), quint16(0), 5000);
        DB_TRY_VERIFY_WITH_TIMEOUT(!m_panel->axis()->status().fault, 5000);
    }

    // Not a check: with DRIVEBENCH_SCREENSHOT=FILE.png (under xvfb-run) it saves the main window
    // at 1366x768 with the simulated ACU enabled and mid-move.
    void screenshotMidMove()
    {
        const QString file = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT");
        if (file.isEmpty())
            QSKIP("set DRIVEBENCH_SCREENSHOT=FILE.png to save the screenshot");
        m_panel->enableDrive();
        DB_TRY_COMPARE_WITH_TIMEOUT(m_panel->motionAxis()->state(), AxisState::Standstill, 5000);
        MotionForm *form = m_panel->motionForm();
        form->selectCommand(CommandKind::MoveAbsolute);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("target"))->setValue(30000);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(8000);
        form->execute();
        DB_TRY_VERIFY_WITH_TIMEOUT(m_acu->motion().position() > 12000, 10000);
        QVERIFY(m_window->grab().save(file));
        m_panel->stopAll(QStringLiteral("screenshot taken"));
    }

private:
    QString allLabels() const
    {
        QStringList texts;
        for (const QLabel *l : m_panel->findChildren<QLabel *>())
            texts << l->text();
        return texts.join(QLatin1Char('\n'));
    }

    std::unique_ptr<SimulatedAcu> m_acu;
    std::unique_ptr<gui::MainWindow> m_window;
    JogPanel *m_panel = nullptr;
    quint64 m_eeprom = 0;
};

QTEST_MAIN(TestJogPanelAcu)
#include "tst_jogpanel_acu.moc"
