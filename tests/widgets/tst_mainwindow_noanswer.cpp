// A command that gets no answer says so where the user looks: a write, an enable, a move and
// an NMT command sent to the demo drive after it fell silent (its links stay up, it answers
// nothing) end in the change log as failed with the cause, in the status bar, and in the panel
// that sent them (object access box, Motion dock, node list), instead of staying pending.
#include "canopen/cannetwork.h"
#include "canopen/nodemonitor.h"
#include "common/demodrive.h"
#include "common/protocols.h"
#include "core/changelog.h"
#include "core/connectionhealth.h"
#include "core/reply.h"
#include "mainwindow.h"
#include "motion/motionaxis.h"
#include "widgets/canopen/networkview.h"
#include "widgets/canopen/nodelist.h"
#include "widgets/canopen/nodelistmodel.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/motion/motionform.h"
#include "widgets/odeditor/objectaccessbox.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::gui::MainWindow;

namespace {
constexpr int kWaitMs = 15000;

// The last entry of one kind; a default entry (kind Write, id 0) when there is none.
ChangeLog::Entry lastOf(const ChangeLog &log, ChangeLog::Kind kind)
{
    for (auto it = log.entries().crbegin(); it != log.entries().crend(); ++it) {
        if (it->kind == kind)
            return *it;
    }
    return {};
}

bool finishedAfter(const ChangeLog &log, ChangeLog::Kind kind, int afterId)
{
    const ChangeLog::Entry e = lastOf(log, kind);
    return e.id > afterId && e.outcome != ChangeLog::Outcome::Pending;
}

QString jogMessage(const MainWindow &window)
{
    auto *label = window.jogPanel()->findChild<QLabel *>(QStringLiteral("message"));
    return label ? label->text() : QString();
}

bool saysNoAnswer(const QString &text)
{
    return text.contains(QLatin1String("no answer"));
}
} // namespace

class TestMainWindowNoAnswer : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
    }

    void enableWithoutAnswer()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo().ok());
        MainWindow window(app::protocolRegistry());
        window.setConfirmation([](const QString &) { return true; });
        window.resize(1366, 768);
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY(opened.ok());
        ConnectionHealth *health = ConnectionHealth::of(*opened);
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        widgets::JogPanel *jog = window.jogPanel();
        QTRY_VERIFY_WITH_TIMEOUT(jog->limitsKnown(), kWaitMs);
        ChangeLog &log = *window.changeLog();
        auto *enable = jog->findChild<QPushButton *>(QStringLiteral("enable"));
        QTRY_VERIFY_WITH_TIMEOUT(enable->isEnabled(), kWaitMs);

        // Enable while the drive hangs.
        demo.setSilent(true);
        int before = lastOf(log, ChangeLog::Kind::Enable).id;
        QTest::mouseClick(enable, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(finishedAfter(log, ChangeLog::Kind::Enable, before), kWaitMs);
        ChangeLog::Entry e = lastOf(log, ChangeLog::Kind::Enable);
        QCOMPARE(e.outcome, ChangeLog::Outcome::Failed);
        QVERIFY2(saysNoAnswer(e.message), qPrintable(e.message));
        QVERIFY2(saysNoAnswer(jogMessage(window)), qPrintable(jogMessage(window)));
        QVERIFY2(window.statusBar()->currentMessage().contains(ChangeLog::kindName(e.kind)),
                 qPrintable(window.statusBar()->currentMessage()));

        // The drive answers again: the health says so, and the next Enable in the same window
        // succeeds (a request lost to the silence does not hold up the ones after it).
        demo.setSilent(false);
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(enable->isEnabled(), kWaitMs);
        before = lastOf(log, ChangeLog::Kind::Enable).id;
        QTest::mouseClick(enable, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(finishedAfter(log, ChangeLog::Kind::Enable, before), kWaitMs);
        e = lastOf(log, ChangeLog::Kind::Enable);
        QVERIFY2(e.outcome == ChangeLog::Outcome::Ok, qPrintable(e.message));
        QTRY_VERIFY_WITH_TIMEOUT(jog->motionAxis()->state() == motion::AxisState::Standstill,
                                 kWaitMs);
    }

    void moveAndWriteWithoutAnswer()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo().ok());
        MainWindow window(app::protocolRegistry());
        window.setConfirmation([](const QString &) { return true; });
        window.resize(1366, 768);
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY(opened.ok());
        DeviceConnection *connection = *opened;
        ConnectionHealth *health = ConnectionHealth::of(connection);
        QTRY_COMPARE_WITH_TIMEOUT(health->status(), ConnectionHealth::Status::Responding, kWaitMs);
        widgets::JogPanel *jog = window.jogPanel();
        QTRY_VERIFY_WITH_TIMEOUT(jog->limitsKnown(), kWaitMs);
        ChangeLog &log = *window.changeLog();
        auto *enable = jog->findChild<QPushButton *>(QStringLiteral("enable"));
        // The reads of a new connection (editor, Motion dock) are answered: a read queued now
        // comes back after them.
        Reply *drained = connection->read({ 0x6041, 0 });
        QTRY_VERIFY_WITH_TIMEOUT(drained->isFinished(), kWaitMs);
        QVERIFY(drained->ok());
        drained->deleteLater();
        QTRY_VERIFY_WITH_TIMEOUT(enable->isEnabled(), kWaitMs);
        int before = lastOf(log, ChangeLog::Kind::Enable).id;
        QTest::mouseClick(enable, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(finishedAfter(log, ChangeLog::Kind::Enable, before), kWaitMs);
        QVERIFY2(lastOf(log, ChangeLog::Kind::Enable).outcome == ChangeLog::Outcome::Ok,
                 qPrintable(lastOf(log, ChangeLog::Kind::Enable).message));
        QTRY_VERIFY_WITH_TIMEOUT(jog->motionAxis()->state() == motion::AxisState::Standstill,
                                 kWaitMs);

        demo.setSilent(true);
        widgets::MotionForm *form = jog->motionForm();
        form->selectCommand(motion::CommandKind::MoveAbsolute);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("target"))->setValue(5000);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(500);
        before = lastOf(log, ChangeLog::Kind::Motion).id;
        QTest::mouseClick(form->findChild<QPushButton *>(QStringLiteral("execute")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(finishedAfter(log, ChangeLog::Kind::Motion, before), kWaitMs);
        ChangeLog::Entry e = lastOf(log, ChangeLog::Kind::Motion);
        QCOMPARE(e.outcome, ChangeLog::Outcome::Failed);
        QVERIFY2(saysNoAnswer(e.message), qPrintable(e.message));
        QVERIFY2(saysNoAnswer(form->statusText()), qPrintable(form->statusText()));
        QVERIFY2(window.statusBar()->currentMessage().contains(QLatin1String("MC_MoveAbsolute")),
                 qPrintable(window.statusBar()->currentMessage()));

        // A write from the object access box.
        widgets::ObjectAccessBox *access = window.objectAccessBox();
        access->setAddressText(QStringLiteral("6083:0"));
        access->findChild<QLineEdit *>(QStringLiteral("value"))->setText(QStringLiteral("1500"));
        before = lastOf(log, ChangeLog::Kind::Write).id;
        access->write();
        QTRY_VERIFY_WITH_TIMEOUT(finishedAfter(log, ChangeLog::Kind::Write, before), kWaitMs);
        e = lastOf(log, ChangeLog::Kind::Write);
        QCOMPARE(e.outcome, ChangeLog::Outcome::Failed);
        QVERIFY2(saysNoAnswer(e.message), qPrintable(e.message));
        QVERIFY2(saysNoAnswer(access->resultText()), qPrintable(access->resultText()));
        QVERIFY2(window.statusBar()->currentMessage().contains(QLatin1String("6083:0")),
                 qPrintable(window.statusBar()->currentMessage()));
        demo.setSilent(false);
    }

    // NMT commands have no protocol answer: the node's heartbeat is the answer. A silent node
    // that sent heartbeats before did not follow; the node list and the change log say so.
    void nmtCommandWithoutAnswer()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startSlcan().ok());
        MainWindow window(app::protocolRegistry());
        window.setConfirmation([](const QString &) { return true; });
        window.resize(1366, 768);
        window.show();
        auto opened = window.openConnection(demo.slcanUri());
        QVERIFY(opened.ok());
        QTRY_VERIFY_WITH_TIMEOUT((*opened)->isConnected(), kWaitMs);
        widgets::NodeList *nodes = window.nodeList();
        QTRY_VERIFY_WITH_TIMEOUT(nodes->model()->rowCount() > 0, kWaitMs);
        nodes->selectNode(50);
        QTRY_VERIFY_WITH_TIMEOUT(nodes->targetNode() == 50, kWaitMs);
        ChangeLog &log = *window.changeLog();
        const canopen::NetworkNode at = canopen::networkNodeOf(*opened);
        QVERIFY(at);

        // Without a heartbeat nothing can confirm the command: ok, and it says so.
        QCOMPARE(at.network->monitor()->state(50), canopen::NmtState::Unknown);
        QVERIFY(nodes->sendCommand(canopen::NmtCommand::Start));
        QTRY_VERIFY_WITH_TIMEOUT(finishedAfter(log, ChangeLog::Kind::Nmt, 0), kWaitMs);
        ChangeLog::Entry e = lastOf(log, ChangeLog::Kind::Nmt);
        QCOMPARE(e.outcome, ChangeLog::Outcome::Ok);
        QVERIFY2(e.message.contains(QLatin1String("not confirmed")), qPrintable(e.message));
        QVERIFY2(nodes->commandStatus().contains(QLatin1String("no heartbeat")),
                 qPrintable(nodes->commandStatus()));

        // With a heartbeat (100 ms) the node's next heartbeats answer.
        Reply *heartbeat = (*opened)->write({ 0x1017, 0 }, QVariant::fromValue<qulonglong>(100));
        QTRY_VERIFY_WITH_TIMEOUT(heartbeat->isFinished(), kWaitMs);
        QVERIFY2(heartbeat->ok(), qPrintable(heartbeat->error().toString()));
        heartbeat->deleteLater();
        QTRY_VERIFY_WITH_TIMEOUT(at.network->monitor()->state(50) != canopen::NmtState::Unknown,
                                 kWaitMs); // heartbeats heard: the node can confirm
        int before = e.id;
        QVERIFY(nodes->sendCommand(canopen::NmtCommand::EnterPreOperational));
        QTRY_VERIFY_WITH_TIMEOUT(finishedAfter(log, ChangeLog::Kind::Nmt, before), kWaitMs);
        e = lastOf(log, ChangeLog::Kind::Nmt);
        QCOMPARE(e.outcome, ChangeLog::Outcome::Ok);
        QVERIFY2(e.message.isEmpty(), qPrintable(e.message));
        QVERIFY2(nodes->commandStatus().contains(QLatin1String("followed")),
                 qPrintable(nodes->commandStatus()));

        demo.setSilent(true);
        before = e.id;
        QVERIFY(nodes->sendCommand(canopen::NmtCommand::Start));
        QCOMPARE(lastOf(log, ChangeLog::Kind::Nmt).outcome, ChangeLog::Outcome::Pending);
        QTRY_VERIFY_WITH_TIMEOUT(finishedAfter(log, ChangeLog::Kind::Nmt, before), kWaitMs);
        e = lastOf(log, ChangeLog::Kind::Nmt);
        QCOMPARE(e.outcome, ChangeLog::Outcome::Failed);
        QVERIFY2(e.message.contains(QLatin1String("no answer")), qPrintable(e.message));
        QVERIFY2(nodes->commandStatus().contains(QLatin1String("no answer")),
                 qPrintable(nodes->commandStatus()));
        QVERIFY2(window.statusBar()->currentMessage().contains(QLatin1String("node 50")),
                 qPrintable(window.statusBar()->currentMessage()));
        // With DRIVEBENCH_SCREENSHOT_DIR=DIR: the network page and the node dock (one list)
        // with the command's outcome, as DIR/screenshot-nmt-no-answer.png.
        if (const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR"); !dir.isEmpty()) {
            window.pages()->setCurrentWidget(window.networkView());
            QCoreApplication::processEvents();
            QVERIFY(window.grab().save(dir + QStringLiteral("/screenshot-nmt-no-answer.png")));
        }
        demo.setSilent(false);
    }
};

QTEST_MAIN(TestMainWindowNoAnswer)
#include "tst_mainwindow_noanswer.moc"
