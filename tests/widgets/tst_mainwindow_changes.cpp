// The main window's change log records what the user changed on a device: a write from the
// object access box, an enable and a move from the Motion dock, a restore of a parameter set and
// a permanent store, each with its outcome, in the Changes dock, in the log, and in a CSV file.
#include "common/demodrive.h"
#include "common/protocols.h"
#include "core/changelog.h"
#include "devices/movingcap/movingcapdrive.h"
#include "mainwindow.h"
#include "motion/motionaxis.h"
#include "parameters/parameterrunner.h"
#include "widgets/common/changelogview.h"
#include "widgets/common/logconsole.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/motion/motionform.h"
#include "widgets/odeditor/objectaccessbox.h"
#include "widgets/parameters/paramcomparemodel.h"
#include "widgets/parameters/paramcompareview.h"
#include "widgets/parameters/parametersetactions.h"

#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::gui::MainWindow;

namespace {
constexpr int kWaitMs = 15000;
constexpr ObjectAddress kVelocity { 0x6081, 0 };

// The entries of one kind, in order.
QList<ChangeLog::Entry> entriesOf(const ChangeLog &log, ChangeLog::Kind kind)
{
    QList<ChangeLog::Entry> out;
    for (const ChangeLog::Entry &e : log.entries()) {
        if (e.kind == kind)
            out << e;
    }
    return out;
}

bool finished(const ChangeLog &log, ChangeLog::Kind kind)
{
    const auto list = entriesOf(log, kind);
    return !list.isEmpty() && list.last().outcome != ChangeLog::Outcome::Pending;
}

} // namespace

class TestMainWindowChanges : public QObject
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

    void writeEnableMoveRestoreAndStoreAreRecorded()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo());
        MainWindow window(app::protocolRegistry());
        window.setConfirmation([](const QString &) { return true; });
        window.resize(1366, 768);
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY2(opened, qPrintable(opened ? QString() : opened.error().toString()));
        DeviceConnection *connection = *opened;
        QTRY_VERIFY_WITH_TIMEOUT(connection->isConnected(), kWaitMs);
        const QString device = connection->uri().toString();
        ChangeLog &log = *window.changeLog();

        // A write from the object access box: old value unknown there, new value, ok.
        widgets::ObjectAccessBox *access = window.objectAccessBox();
        access->setAddressText(QStringLiteral("6083:0"));
        access->findChild<QLineEdit *>(QStringLiteral("value"))->setText(QStringLiteral("1500"));
        access->write();
        QTRY_VERIFY_WITH_TIMEOUT(finished(log, ChangeLog::Kind::Write), kWaitMs);
        ChangeLog::Entry write = entriesOf(log, ChangeLog::Kind::Write).last();
        QCOMPARE(write.device, device);
        QVERIFY2(write.object.startsWith(QLatin1String("6083:0 ")), qPrintable(write.object));
        QVERIFY2(write.newValue.startsWith(QLatin1String("1500")), qPrintable(write.newValue));
        QCOMPARE(write.outcome, ChangeLog::Outcome::Ok);
        QVERIFY(write.storable && !write.stored);

        // Input refused before anything is sent (outside the object's limits) changes nothing
        // on the device: no entry.
        access->findChild<QLineEdit *>(QStringLiteral("value"))->setText(QStringLiteral("50000"));
        access->write();
        QCoreApplication::processEvents();
        QCOMPARE(entriesOf(log, ChangeLog::Kind::Write).size(), 1);

        // Enable and a move from the Motion dock.
        widgets::JogPanel *jog = window.jogPanel();
        QTRY_VERIFY_WITH_TIMEOUT(jog->limitsKnown(), kWaitMs);
        QTest::mouseClick(jog->findChild<QPushButton *>(QStringLiteral("enable")), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(finished(log, ChangeLog::Kind::Enable), kWaitMs);
        QCOMPARE(entriesOf(log, ChangeLog::Kind::Enable).last().outcome, ChangeLog::Outcome::Ok);
        QTRY_VERIFY_WITH_TIMEOUT(jog->motionAxis()->state() == motion::AxisState::Standstill,
                                 kWaitMs);
        widgets::MotionForm *form = jog->motionForm();
        form->selectCommand(motion::CommandKind::MoveAbsolute);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("target"))->setValue(1000);
        form->findChild<QDoubleSpinBox *>(QStringLiteral("velocity"))->setValue(2000);
        QTest::mouseClick(form->findChild<QPushButton *>(QStringLiteral("execute")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(finished(log, ChangeLog::Kind::Motion), kWaitMs);
        const ChangeLog::Entry move = entriesOf(log, ChangeLog::Kind::Motion).last();
        QCOMPARE(move.object, QStringLiteral("MC_MoveAbsolute"));
        QVERIFY2(move.newValue.contains(QLatin1String("1000")), qPrintable(move.newValue));
        QCOMPARE(move.outcome, ChangeLog::Outcome::Ok);
        QVERIFY(qAbs(demo.drive().axis().position() - 1000) < 2);
        QTest::mouseClick(jog->findChild<QPushButton *>(QStringLiteral("disable")), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(finished(log, ChangeLog::Kind::Disable), kWaitMs);

        // A restore of one changed row.
        ParameterBackup runner(connection);
        QSignalSpy done(&runner, &ParameterBackup::finished);
        runner.start();
        QVERIFY(done.wait(20000));
        auto result = runner.result();
        QVERIFY(result.ok());
        ParameterSet set = result.value();
        ParameterEntry velocity = *set.find(kVelocity);
        const qulonglong original = velocity.raw.toULongLong();
        velocity.raw = QVariant::fromValue<qulonglong>(velocity.raw.toULongLong() + 11);
        set.insert(velocity);
        widgets::ParamCompareView *compare = window.compareView();
        compare->setFileSet(set, QStringLiteral("changed.dbp"));
        QTRY_VERIFY_WITH_TIMEOUT(!compare->isBusy() && compare->model()->selection().size() == 1,
                                 kWaitMs);
        QSignalSpy restored(compare, &widgets::ParamCompareView::restoreFinished);
        compare->startRestore();
        QVERIFY(restored.wait(kWaitMs));
        const auto restores = entriesOf(log, ChangeLog::Kind::Restore);
        QCOMPARE(restores.size(), 1);
        QVERIFY2(restores.first().object.startsWith(QLatin1String("6081:0")),
                 qPrintable(restores.first().object));
        QCOMPARE(restores.first().oldValue, QString::number(original));
        QCOMPARE(restores.first().newValue, QString::number(velocity.raw.toULongLong()));
        QCOMPARE(restores.first().outcome, ChangeLog::Outcome::Ok);
        QVERIFY(log.unstoredCount(device) >= 2); // the write and the restored row

        // Storing permanently marks the earlier writes stored.
        window.parameterActions()->storeNow();
        QTRY_VERIFY_WITH_TIMEOUT(finished(log, ChangeLog::Kind::Store), kWaitMs);
        QCOMPARE(entriesOf(log, ChangeLog::Kind::Store).last().outcome, ChangeLog::Outcome::Ok);
        QCOMPARE(log.unstoredCount(device), 0);
        QVERIFY(log.find(write.id)->stored);

        // The Changes dock lists them; the log shows each as a change line; the CSV keeps them.
        QCOMPARE(window.changeLogView()->table()->model()->rowCount(), log.count());
        window.logConsole()->setFilter(widgets::LogConsole::Filter::Changes);
        const QString lines = window.logConsole()->toPlainText();
        QVERIFY2(lines.contains(QLatin1String("write 6083:0")), qPrintable(lines));
        QVERIFY2(lines.contains(QLatin1String("enable MC_Power")), qPrintable(lines));
        QVERIFY2(lines.contains(QLatin1String("motion MC_MoveAbsolute")), qPrintable(lines));
        QVERIFY2(lines.contains(QLatin1String("restore 6081:0")), qPrintable(lines));
        const QString path = m_dir.filePath(QStringLiteral("changes.csv"));
        QCOMPARE(window.changeLogView()->saveTo(path), QString());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString csv = QString::fromUtf8(file.readAll());
        QCOMPARE(csv.count(QLatin1Char('\n')), log.count() + 1);
        QVERIFY(csv.contains(QLatin1String("\"MC_MoveAbsolute\"")));

        if (const QByteArray dir = qgetenv("DRIVEBENCH_SCREENSHOT_CHANGES"); !dir.isEmpty()) {
            window.findChild<QDockWidget *>(QStringLiteral("changesDock"))->raise();
            QCoreApplication::processEvents();
            QVERIFY(window.grab().save(QString::fromLocal8Bit(dir)
                                       + QStringLiteral("/screenshot-changes.png")));
        }
    }
};

QTEST_MAIN(TestMainWindowChanges)
#include "tst_mainwindow_changes.moc"
