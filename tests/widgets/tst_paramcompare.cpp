#include "common/demodrive.h"
#include "common/protocols.h"
#include "devices/movingcap/movingcapdrive.h"
#include "fakeconnection.h"
#include "mainwindow.h"
#include "parameters/parameterrunner.h"
#include "pdftext.h"
#include "resources/builtindescriptions.h"
#include "widgets/common/recentfolder.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/odeditor/odeditorfilter.h"
#include "widgets/odeditor/odeditormodel.h"
#include "widgets/odeditor/odeditorpoller.h"
#include "widgets/parameters/paramcomparemodel.h"
#include "widgets/parameters/paramcomparereport.h"
#include "widgets/parameters/paramcompareview.h"
#include "widgets/parameters/parametersetactions.h"

#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>
#include <QTreeWidget>

using namespace db;
using db::test::FakeConnection;
using db::widgets::ParamCompareModel;
using db::widgets::ParamCompareView;

namespace {
constexpr ObjectAddress kVelocity { 0x6081, 0 };
constexpr ObjectAddress kWindow { 0x3401, 3 };
constexpr ObjectAddress kPositionWindow { 0x6067, 0 };

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

QVariant u32(qulonglong v)
{
    return QVariant::fromValue<qulonglong>(v);
}

// A set that differs from `set` in the given rows (+delta on an unsigned value).
ParameterSet changed(ParameterSet set, const QList<ObjectAddress> &rows, qulonglong delta)
{
    for (ObjectAddress a : rows) {
        ParameterEntry e = *set.find(a);
        e.raw = u32(e.raw.toULongLong() + delta);
        set.insert(e);
    }
    return set;
}

Result<ParameterSet> backup(DeviceConnection *connection)
{
    ParameterBackup runner(connection);
    QSignalSpy done(&runner, &ParameterBackup::finished);
    runner.start();
    if (!done.wait(20000))
        return Error(Error::Kind::Timeout, QStringLiteral("backup did not finish"));
    return runner.result();
}
} // namespace

// Level 4: the parameter-set page and commands against the simulated MovingCap over RefGo and
// the FakeConnection (for writes the device rejects).
class TestParamCompare : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    std::unique_ptr<FakeConnection> fake()
    {
        auto f = std::make_unique<FakeConnection>();
        f->setDictionary(resources::movingCapDictionary());
        for (const ObjectDef &def : f->dictionary().objects()) {
            f->setValue(def.address,
                        def.defaultValue.isValid() ? def.defaultValue
                                                   : codec::normalize(def.type, 0).valueOr({}));
        }
        f->open();
        return f;
    }

private Q_SLOTS:
    void countsAndSelectiveRestoreAgainstTheSimulator()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        auto created = app::protocolRegistry().create(demo.refgoUri());
        QVERIFY(created.ok());
        std::shared_ptr<DeviceConnection> connection = created.value();
        connection->open();
        QTRY_VERIFY_WITH_TIMEOUT(connection->isConnected(), 10000);

        const auto original = backup(connection.get());
        QVERIFY2(original.ok(), qPrintable(original.error().toString()));
        const QList<ObjectAddress> rows { kVelocity, kWindow, kPositionWindow };
        const ParameterSet file = changed(original.value(), rows, 7);
        const QString path = m_dir.filePath(QStringLiteral("three.dbp"));
        QVERIFY(file.save(path).ok());

        ParamCompareView view;
        view.resize(1200, 700);
        view.setConnection(connection.get());
        view.show();
        QSignalSpy compared(&view, &ParamCompareView::comparisonChanged);
        QVERIFY(view.loadFile(path).ok());
        QTRY_VERIFY_WITH_TIMEOUT(!view.isBusy() && compared.count() >= 2, 10000);
        const ParameterComparison &c = view.model()->comparison();
        QCOMPARE(c.count(CompareStatus::Changed), 3);
        QCOMPARE(c.count(CompareStatus::Missing), 0);
        QCOMPARE(c.count(CompareStatus::Unchanged), file.size() - 3);
        QVERIFY(view.countsText().contains(QStringLiteral("3 changed")));
        // Loading never writes.
        QCOMPARE(demo.drive().read(kVelocity).value(), original->find(kVelocity)->raw);

        // "Only differences" is on from the start.
        QVERIFY(view.findChild<QCheckBox *>(QStringLiteral("onlyDifferences"))->isChecked());
        QCOMPARE(view.filter()->rowCount(), 3);
        QList<ObjectAddress> sorted = rows;
        std::sort(sorted.begin(), sorted.end());
        QCOMPARE(view.model()->selection(), sorted); // differences are preselected

        // Restore two of the three rows only.
        view.model()->setSelected(kPositionWindow, false);
        QSignalSpy restored(&view, &ParamCompareView::restoreFinished);
        view.startRestore();
        QVERIFY(restored.wait(20000));
        const RestoreReport report = *view.lastReport();
        QCOMPARE(report.rows.size(), 2);
        QCOMPARE(report.count(RestoreOutcome::Verified), 2);
        QVERIFY(report.succeeded());
        QCOMPARE(demo.drive().read(kVelocity).value().toULongLong(),
                 file.find(kVelocity)->raw.toULongLong());
        QCOMPARE(demo.drive().read(kWindow).value().toULongLong(),
                 file.find(kWindow)->raw.toULongLong());
        QCOMPARE(demo.drive().read(kPositionWindow).value(), original->find(kPositionWindow)->raw);
        // The page reads the device again: one difference left.
        QTRY_VERIFY_WITH_TIMEOUT(
            !view.isBusy() && view.model()->comparison().count(CompareStatus::Changed) == 1, 10000);
        QVERIFY(view.findChild<widgets::ParamCompareReport *>());
        connection->close();
    }

    void missingRowsAreCounted()
    {
        auto f = fake();
        QTRY_VERIFY(f->isConnected());
        auto set = backup(f.get());
        QVERIFY(set.ok());
        ParameterSet file = set.value();
        QVERIFY(file.remove(kVelocity));
        ParamCompareView view;
        view.setConnection(f.get());
        view.setFileSet(file, QStringLiteral("file"));
        QTRY_VERIFY(!view.isBusy() && view.model()->comparison().rows.size() == set->size());
        QCOMPARE(view.model()->comparison().count(CompareStatus::Missing), 1);
        QCOMPARE(view.model()->comparison().count(CompareStatus::Changed), 0);
        // A missing row has no file value and cannot be selected for restore.
        const auto &rows = view.model()->comparison().rows;
        const auto it = std::find_if(rows.begin(), rows.end(),
                                     [](const CompareRow &r) { return r.address == kVelocity; });
        QVERIFY(it != rows.end());
        QCOMPARE(it->status, CompareStatus::Missing);
        const QModelIndex check =
            view.model()->index(int(it - rows.begin()), ParamCompareModel::Select);
        QVERIFY(!view.model()->setData(check, Qt::Checked, Qt::CheckStateRole));
        QVERIFY(f->writes.isEmpty());

        // Save Report: every row as CSV, the missing one with its status.
        const QString csv = m_dir.filePath(QStringLiteral("report.csv"));
        const auto saved = view.saveReportCsv(csv);
        QVERIFY2(saved.ok(), qPrintable(saved.error().toString()));
        QFile report(csv);
        QVERIFY(report.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(report.readAll()).trimmed().split(u'\n');
        QCOMPARE(lines.size(), rows.size() + 1);
        QCOMPARE(lines.first(), QStringLiteral("Address,Name,Device,File,Unit,Status"));
        QVERIFY2(
            lines.filter(QStringLiteral("6081:0,")).value(0).endsWith(QStringLiteral(",missing")),
            qPrintable(lines.filter(QStringLiteral("6081:0,")).join(u'|')));
        QVERIFY(!ParamCompareView().saveReportCsv(csv + QStringLiteral("2")).ok()); // nothing yet
    }

    void rejectedWriteIsInTheReport()
    {
        auto f = fake();
        QTRY_VERIFY(f->isConnected());
        auto set = backup(f.get());
        QVERIFY(set.ok());
        f->setFailure(kWindow,
                      Error(Error::Kind::DeviceError,
                            QStringLiteral("SDO abort 06090030: value "
                                           "range exceeded")));
        ParamCompareView view;
        view.setConnection(f.get());
        view.setFileSet(changed(set.value(), { kVelocity, kWindow }, 3), QStringLiteral("file"));
        QTRY_VERIFY(!view.isBusy() && view.model()->selection().size() == 2);
        QSignalSpy restored(&view, &ParamCompareView::restoreFinished);
        view.startRestore();
        QVERIFY(restored.wait(10000));
        const RestoreReport report = *view.lastReport();
        QVERIFY(!report.succeeded());
        QCOMPARE(report.count(RestoreOutcome::Verified), 1);
        QCOMPARE(report.count(RestoreOutcome::Failed), 1);
        auto *dialog = view.findChild<widgets::ParamCompareReport *>();
        QVERIFY(dialog);
        QTreeWidgetItem *first = dialog->rows()->topLevelItem(0); // failures first
        QCOMPARE(first->text(0), restoreOutcomeName(RestoreOutcome::Failed));
        QCOMPARE(first->text(1), kWindow.toString());
        QVERIFY(first->text(4).contains(QStringLiteral("06090030")));
        QVERIFY(view.statusText().contains(QStringLiteral("1 failed")));
        // Only the velocity was written.
        QCOMPARE(f->writes.size(), 1);
        QCOMPARE(f->writes.first().first, kVelocity);
    }

    // A set is compared only with the kind of device it came from (1018h vendor and product).
    void anotherDeviceIsNotCompared()
    {
        auto f = fake();
        f->setValue({ 0x1018, 2 }, QVariant::fromValue(0x100u));
        QTRY_VERIFY(f->isConnected());
        auto set = backup(f.get());
        QVERIFY(set.ok());
        QCOMPARE(set->identity.productCode, 0x100u);
        f->setValue({ 0x1018, 2 }, QVariant::fromValue(0x200u)); // another product now
        ParamCompareView view;
        view.setConnection(f.get());
        view.setFileSet(set.value(), QStringLiteral("file"));
        QTRY_VERIFY2(!view.isBusy() && view.statusText().contains(QStringLiteral("Not compared")),
                     qPrintable(view.statusText()));
        QVERIFY2(view.statusText().contains(QStringLiteral("00000100h"))
                     && view.statusText().contains(QStringLiteral("00000200h")),
                 qPrintable(view.statusText()));
        QCOMPARE(view.model()->comparison().rows.size(), 0);
        QVERIFY(!view.findChild<QPushButton *>(QStringLiteral("restoreSelected"))->isEnabled());

        f->setValue({ 0x1018, 2 }, QVariant::fromValue(0x100u)); // the right device again
        view.refreshDevice();
        QTRY_VERIFY(!view.isBusy() && view.model()->comparison().rows.size() == set->size());
        QVERIFY(!view.statusText().contains(QStringLiteral("Not compared")));
    }

    // A backup records the unit's serial number (1018h.4) and keeps it in the file; the same
    // product with another serial number is compared and restored only once the user said so;
    // another product is refused as before, whatever the serial number.
    void anotherUnitNeedsConfirmation()
    {
        auto f = fake();
        f->setValue({ 0x1018, 2 }, QVariant::fromValue(0x100u));
        f->setValue({ 0x1018, 4 }, QVariant::fromValue(0x1E240u));
        QTRY_VERIFY(f->isConnected());
        auto set = backup(f.get());
        QVERIFY2(set.ok(), qPrintable(set ? QString() : set.error().toString()));
        QCOMPARE(set->serialNumber, QStringLiteral("0x0001E240"));
        QVERIFY(!set->contains({ 0x1018, 4 })); // identity, not a parameter
        const QString path = m_dir.filePath(QStringLiteral("unit.dbp"));
        QVERIFY(set->save(path).ok());
        const auto loaded = ParameterSet::load(path);
        QVERIFY(loaded.ok());
        QCOMPARE(loaded->serialNumber, QStringLiteral("0x0001E240"));

        // The same unit: no question.
        QStringList asked;
        bool answer = false;
        ParamCompareView view;
        view.setConfirmation([&](const QString &q) {
            asked << q;
            return answer;
        });
        view.setConnection(f.get());
        view.setFileSet(loaded.value(), QStringLiteral("unit.dbp"));
        QTRY_VERIFY(!view.isBusy() && view.model()->comparison().rows.size() == set->size());
        QVERIFY(asked.isEmpty());

        // Another unit, the user says no: nothing compared, nothing to restore.
        f->setValue({ 0x1018, 4 }, QVariant::fromValue(0x1E241u));
        view.refreshDevice();
        QTRY_VERIFY(!view.isBusy() && asked.size() == 1);
        QVERIFY2(asked.first().contains(QStringLiteral("0x0001E240"))
                     && asked.first().contains(QStringLiteral("0x0001E241")),
                 qPrintable(asked.first()));
        QCOMPARE(view.model()->comparison().rows.size(), 0);
        QVERIFY2(view.statusText().contains(QStringLiteral("Not compared")),
                 qPrintable(view.statusText()));
        QVERIFY(!view.findChild<QPushButton *>(QStringLiteral("restoreSelected"))->isEnabled());

        // The user says yes: compared, with the warning in the status line; asked once only.
        answer = true;
        view.refreshDevice();
        QTRY_VERIFY(!view.isBusy() && view.model()->comparison().rows.size() == set->size());
        QCOMPARE(asked.size(), 2);
        QVERIFY2(view.statusText().contains(QStringLiteral("another unit")),
                 qPrintable(view.statusText()));
        view.setCompareWithDefaults(false);
        view.setCompareWithDefaults(true);
        QCOMPARE(asked.size(), 2);

        // Another product with the file's serial number: refused without a question.
        f->setValue({ 0x1018, 2 }, QVariant::fromValue(0x200u));
        f->setValue({ 0x1018, 4 }, QVariant::fromValue(0x1E240u));
        view.refreshDevice();
        QTRY_VERIFY(!view.isBusy() && view.statusText().contains(QStringLiteral("Not compared")));
        QVERIFY2(view.statusText().contains(QStringLiteral("00000200h")),
                 qPrintable(view.statusText()));
        QCOMPARE(asked.size(), 2);

        // A file without a serial number (older files, devices without 1018h.4): no question.
        ParameterSet old = loaded.value();
        old.serialNumber.clear();
        f->setValue({ 0x1018, 2 }, QVariant::fromValue(0x100u));
        f->setValue({ 0x1018, 4 }, QVariant::fromValue(0x999u));
        view.setFileSet(old, QStringLiteral("old.dbp"));
        QTRY_VERIFY(!view.isBusy() && view.model()->comparison().rows.size() == set->size());
        QCOMPARE(asked.size(), 2);
    }

    // Save Report as PDF: the device's identity, the date, the file and the differences table,
    // written atomically (a whole new file or the old one; no temporary file left behind).
    void reportAsPdf()
    {
        auto f = fake();
        f->setValue({ 0x1018, 1 }, QVariant::fromValue(0x2D6u));
        f->setValue({ 0x1018, 2 }, QVariant::fromValue(0x100u));
        f->setValue({ 0x1018, 4 }, QVariant::fromValue(0x1E240u));
        QTRY_VERIFY(f->isConnected());
        auto set = backup(f.get());
        QVERIFY(set.ok());
        ParamCompareView view;
        view.setConnection(f.get());
        view.setFileSet(changed(set.value(), { kVelocity }, 7), QStringLiteral("commissioned.dbp"));
        QTRY_VERIFY(!view.isBusy()
                    && view.model()->comparison().count(CompareStatus::Changed) == 1);

        const QString path = m_dir.filePath(QStringLiteral("report/comparison.pdf"));
        QVERIFY(QDir().mkpath(QFileInfo(path).path()));
        {
            QFile old(path);
            QVERIFY(old.open(QIODevice::WriteOnly));
            old.write("old report");
        }
        QVERIFY(!ParamCompareView().saveReportPdf(path).ok()); // nothing compared there
        QCOMPARE(readAll(path), QByteArray("old report"));
        const auto saved = view.saveReportPdf(path);
        QVERIFY2(saved.ok(), qPrintable(saved ? QString() : saved.error().toString()));
        const QByteArray pdf = readAll(path);
        QVERIFY(pdf.startsWith("%PDF-"));
        QVERIFY(pdf.trimmed().endsWith("%%EOF"));
        QCOMPARE(QDir(QFileInfo(path).path()).entryList(QDir::Files),
                 QStringList { QStringLiteral("comparison.pdf") });
        const QString text = test::pdfText(pdf);
        const QString device = f->uri().toString();
        const qulonglong fileVelocity = set->find(kVelocity)->raw.toULongLong() + 7;
        for (const QString &expected :
             { QStringLiteral("Parameter Comparison"), QStringLiteral("0x0001E240"),
               QStringLiteral("00000100h"), QStringLiteral("commissioned.dbp"),
               QStringLiteral("6081:0"), QString::number(fileVelocity),
               QString::number(QDate::currentDate().year()), device })
            QVERIFY2(text.contains(expected),
                     qPrintable(QStringLiteral("'%1' not in: %2").arg(expected, text)));
        // Rows without a difference are not in the table.
        QVERIFY(!text.contains(QStringLiteral("6083:0")));

        const auto missing = view.saveReportPdf(m_dir.filePath(QStringLiteral("no/such/r.pdf")));
        QVERIFY(!missing.ok());
        QVERIFY2(missing.error().message().contains(QStringLiteral("r.pdf")),
                 qPrintable(missing.error().message()));
    }

    // File against file: no device is read or written.
    void fileAgainstFile()
    {
        auto f = fake();
        QTRY_VERIFY(f->isConnected());
        auto set = backup(f.get());
        QVERIFY(set.ok());
        const QString other = m_dir.filePath(QStringLiteral("other.dbp"));
        QVERIFY(changed(set.value(), { kVelocity, kWindow }, 5).save(other).ok());
        ParamCompareView view;
        view.setFileSet(set.value(), QStringLiteral("first.dbp"));
        const int readsBefore = f->readCount;
        QVERIFY(view.loadReferenceFile(other).ok());
        QVERIFY(view.comparesTwoFiles());
        const ParameterComparison &c = view.model()->comparison();
        QCOMPARE(c.sideNames.value(0), QStringLiteral("other.dbp"));
        QCOMPARE(c.count(CompareStatus::Changed), 2);
        QCOMPARE(c.count(CompareStatus::Unchanged), set->size() - 2);
        QVERIFY(view.statusText().contains(QStringLiteral("Compared first.dbp with other.dbp")));
        QVERIFY(!view.findChild<QPushButton *>(QStringLiteral("restoreSelected"))->isEnabled());
        view.setConnection(f.get()); // a device appears: the two files stay compared
        QCOMPARE(view.model()->comparison().sideNames.value(0), QStringLiteral("other.dbp"));
        QVERIFY(!view.findChild<QPushButton *>(QStringLiteral("restoreSelected"))->isEnabled());
        QCOMPARE(f->readCount, readsBefore);
        QVERIFY(f->writes.isEmpty());
        view.refreshDevice(); // back to the device
        QVERIFY(!view.comparesTwoFiles());
        QTRY_VERIFY(!view.isBusy()
                    && view.model()->comparison().sideNames.value(0) == QStringLiteral("Device"));
    }

    // File dialogs start in the folder the last file of their kind went to.
    void dialogsStartInTheLastFolder()
    {
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QTemporaryDir sets;
        QVERIFY(sets.isValid());
        QCOMPARE(widgets::recentFolder(QStringLiteral("never-used")), QDir::homePath());
        widgets::rememberFolder(QStringLiteral("dbp"), sets.filePath(QStringLiteral("a.dbp")));
        QCOMPARE(widgets::recentFolder(QStringLiteral("dbp")), QDir(sets.path()).absolutePath());
        QCOMPARE(widgets::recentFolder(QStringLiteral("dcf")), QDir::homePath()); // per kind
        widgets::rememberFolder(QStringLiteral("dbp"), QString()); // cancelled: unchanged
        QCOMPARE(widgets::recentFolder(QStringLiteral("dbp")), QDir(sets.path()).absolutePath());
    }

    void corruptFileChangesNothing()
    {
        auto f = fake();
        QTRY_VERIFY(f->isConnected());
        const QString path = m_dir.filePath(QStringLiteral("corrupt.dbp"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("# drivebench parameter set\nformat 1\nentries 2\n6081:0 \"x\" UNSIGNED32 1");
        file.close();
        ParamCompareView view;
        view.setConnection(f.get());
        const auto loaded = view.loadFile(path);
        QVERIFY(!loaded.ok());
        QVERIFY(view.statusText().contains(QStringLiteral("corrupt.dbp")));
        // A file's error names the file and line, not a device's "malformed answer".
        QVERIFY2(view.statusText().startsWith(path + QStringLiteral(":4: ")),
                 qPrintable(view.statusText()));
        QVERIFY(!view.statusText().contains(QStringLiteral("answer")));
        QVERIFY(!view.hasFileSet());
        QVERIFY(f->writes.isEmpty());
        QCOMPARE(f->readCount, 0);
    }

    void backupStoreAndCancel()
    {
        auto f = fake();
        f->setValue({ 0x1018, 2 }, QVariant::fromValue(0xABCDEFu));
        f->setValue({ 0x1018, 3 }, QVariant::fromValue(0x20003u));
        QTRY_VERIFY(f->isConnected());
        widgets::ParameterSetActions actions(nullptr);
        actions.setConnection(f.get());
        QVERIFY(actions.backUpAction()->isEnabled());
        QSignalSpy finished(&actions, &widgets::ParameterSetActions::backupFinished);
        const QString path = m_dir.filePath(QStringLiteral("backup.dbp"));
        actions.backUpTo(path);
        QVERIFY(finished.wait(10000));
        QCOMPARE(finished.first().first().toBool(), true);
        const auto loaded = ParameterSet::load(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().toString()));
        QVERIFY(loaded->contains(kVelocity));

        QSignalSpy message(&actions, &widgets::ParameterSetActions::message);
        const QString dcf = m_dir.filePath(QStringLiteral("device.dcf"));
        actions.exportDcfTo(dcf);
        QVERIFY(message.wait(10000));
        QVERIFY2(message.first().at(1).toBool(), qPrintable(message.first().first().toString()));
        QFile dcfFile(dcf);
        QVERIFY(dcfFile.open(QIODevice::ReadOnly));
        const QByteArray dcfText = dcfFile.readAll();
        QVERIFY(dcfText.contains("[DeviceInfo]"));
        QVERIFY(dcfText.contains("[6081]"));
        // The identity is the device's, numeric, never a made-up 0.
        QVERIFY2(dcfText.contains("ProductNumber=0x00ABCDEF\n"), dcfText.constData());
        QVERIFY(dcfText.contains("RevisionNumber=0x00020003\n"));
        QVERIFY(!dcfText.contains("=0x00000000\n[DeviceComissioning]"));
        QVERIFY(!dcfText.contains("ProductNumber=0x00000000"));

        // Cancel while reading: nothing is saved.
        f->replyDelayMs = 20;
        finished.clear();
        const QString cancelled = m_dir.filePath(QStringLiteral("cancelled.dbp"));
        const int readsBefore = f->readCount;
        actions.backUpTo(cancelled);
        QVERIFY(actions.isBusy());
        QTRY_VERIFY(f->readCount > readsBefore + 5);
        actions.cancel();
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(finished.first().first().toBool(), false);
        QVERIFY(!QFile::exists(cancelled));

        f->replyDelayMs = 0;
        QTRY_VERIFY(!actions.isBusy() && actions.backUpAction()->isEnabled());
    }

    // Parameters > Back Up… with objects that cannot be read: the good file stays, the objects
    // read go to a .partial file, the message names the failed objects.
    void backupWithFailedReadsKeepsTheFile()
    {
        auto f = fake();
        QTRY_VERIFY(f->isConnected());
        widgets::ParameterSetActions actions(nullptr);
        actions.setConnection(f.get());
        QSignalSpy finished(&actions, &widgets::ParameterSetActions::backupFinished);
        const QString path = m_dir.filePath(QStringLiteral("kept.dbp"));
        actions.backUpTo(path);
        QVERIFY(finished.wait(10000));
        QVERIFY(finished.first().first().toBool());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray good = file.readAll();
        file.close();

        f->setFailure(kVelocity, Error(Error::Kind::DeviceError, QStringLiteral("abort 06020000")));
        f->setFailure({ 0x1018, 2 }, Error(Error::Kind::Malformed, QStringLiteral("wrong echo")));
        QSignalSpy message(&actions, &widgets::ParameterSetActions::message);
        finished.clear();
        actions.backUpTo(path);
        QVERIFY(finished.wait(10000));
        QCOMPARE(finished.first().first().toBool(), false);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), good);
        QCOMPARE(message.size(), 1);
        const QString text = message.first().first().toString();
        QVERIFY(!message.first().at(1).toBool());
        QVERIFY2(text.contains(QLatin1String("not written")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("6081:0")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("1018:2")), qPrintable(text));
        const auto partial = ParameterSet::load(path + QStringLiteral(".partial"));
        QVERIFY2(partial.ok(), qPrintable(partial.error().toString()));
        QVERIFY(!partial->contains(kVelocity));
        QVERIFY(partial->contains(kWindow));
        QVERIFY(!partial->productCodeKnown);
    }

    void storeWritesTheSignature()
    {
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        auto created = app::protocolRegistry().create(demo.refgoUri());
        QVERIFY(created.ok());
        std::shared_ptr<DeviceConnection> connection = created.value();
        connection->open();
        QTRY_VERIFY_WITH_TIMEOUT(connection->isConnected(), 10000);
        widgets::ParameterSetActions actions(nullptr);
        actions.setConnection(connection.get());
        QVERIFY(actions.storeAction()->isEnabled());
        QSignalSpy message(&actions, &widgets::ParameterSetActions::message);
        actions.storeNow();
        QVERIFY(message.wait(10000));
        QVERIFY2(message.first().at(1).toBool(), qPrintable(message.first().first().toString()));
        connection->close();
    }

    void mainWindowWiresThePages()
    {
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        gui::MainWindow window(app::protocolRegistry());
        QStringList tabs;
        for (int i = 0; i < window.pages()->count(); ++i)
            tabs.append(window.pages()->tabText(i));
        QVERIFY(tabs.contains(QStringLiteral("Object Dictionary")));
        QVERIFY(tabs.contains(QStringLiteral("Parameter Sets")));
        const auto menus = window.menuBar()->actions();
        const auto params = std::find_if(menus.begin(), menus.end(), [](QAction *a) {
            return a->text() == QStringLiteral("&Parameters");
        });
        QVERIFY(params != menus.end());
        QCOMPARE((*params)->menu()->actions().size(), 7); // 5 commands, 2 separators
        QVERIFY(!window.parameterActions()->backUpAction()->isEnabled());

        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY(opened.ok());
        QCOMPARE(window.odEditor()->connection(), opened.value());
        QCOMPARE(window.compareView()->connection(), opened.value());
        QTRY_VERIFY_WITH_TIMEOUT(window.parameterActions()->backUpAction()->isEnabled(), 10000);
        QVERIFY(window.parameterActions()->storeAction()->isEnabled());
        window.close();
    }

    // Not a test: with DRIVEBENCH_SCREENSHOT_DIR set, saves the editor and compare pages of the
    // main window on the demo drive (docs/screenshot-odeditor.png, docs/screenshot-compare.png).
    void screenshots()
    {
        const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
        if (dir.isEmpty())
            QSKIP("set DRIVEBENCH_SCREENSHOT_DIR to write the screenshots");
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        gui::MainWindow window(app::protocolRegistry());
        window.resize(1400, 900);
        window.show();
        auto opened = window.openConnection(demo.refgoUri());
        QVERIFY(opened.ok());
        DeviceConnection *connection = opened.value();
        QTRY_VERIFY_WITH_TIMEOUT(connection->isConnected(), 10000);
        // A drive in Operation enabled, so that the statusword has bits to show.
        for (quint16 cw : { 0x06, 0x07, 0x0F })
            QVERIFY(demo.drive().write({ 0x6040, 0 }, QVariant::fromValue<qulonglong>(cw)).ok());

        // Room for the page: the motion and node docks are not what these pictures are about.
        for (const char *name :
             { "motionDock", "nodeListDock", "logDock", "canMonitorDock", "morseDock" }) {
            if (auto *dock = window.findChild<QDockWidget *>(QString::fromLatin1(name)))
                dock->hide();
        }
        window.resize(1400, 900);
        widgets::OdEditor *editor = window.odEditor();
        window.pages()->setCurrentWidget(editor);
        QTRY_VERIFY_WITH_TIMEOUT(editor->poller()->pending() == 0
                                     && editor->model()->value({ 0x6041, 0 }).isValid(),
                                 10000);
        QTreeView *view = editor->view();
        const auto at = [editor](ObjectAddress a) {
            return editor->filter()->mapFromSource(editor->model()->indexOf(a));
        };
        view->collapseAll();
        view->expand(view->model()->index(2, 0)); // device profile
        view->expand(view->model()->index(0, 0)); // communication
        view->expand(at({ 0x1018, 1 }).parent());
        view->setCurrentIndex(at({ 0x6041, 0 }));
        view->scrollTo(at({ 0x6040, 0 }), QAbstractItemView::PositionAtTop);
        view->scrollTo(at({ 0x1018, 4 }), QAbstractItemView::EnsureVisible);
        editor->model()->setData(editor->model()->indexOf({ 0x6083, 0 }, 4),
                                 QStringLiteral("50000")); // refused: outside 1 .. 20000
        QCoreApplication::processEvents(); // the refused cell's repaint
        QVERIFY(window.grab().save(dir + QStringLiteral("/screenshot-odeditor.png")));

        const auto original = backup(connection);
        QVERIFY(original.ok());
        ParameterSet file = changed(original.value(), { kVelocity, kWindow, kPositionWindow }, 25);
        QVERIFY(file.remove({ 0x6073, 0 })); // missing from the file
        const QString path = m_dir.filePath(QStringLiteral("line-3-axis-2.dbp"));
        QVERIFY(file.save(path).ok());
        widgets::ParamCompareView *compare = window.compareView();
        window.pages()->setCurrentWidget(compare);
        QVERIFY(compare->loadFile(path).ok());
        QTRY_VERIFY_WITH_TIMEOUT(!compare->isBusy() && compare->model()->rowCount() > 0, 10000);
        compare->table()->scrollTo(
            compare->filter()->mapFromSource(compare->model()->index(
                int(std::find_if(compare->model()->comparison().rows.begin(),
                                 compare->model()->comparison().rows.end(),
                                 [](const CompareRow &r) { return r.address.index >= 0x6040; })
                    - compare->model()->comparison().rows.begin() - 6),
                0)),
            QAbstractItemView::PositionAtTop);
        QCoreApplication::processEvents(); // the scroll and the repaint
        QVERIFY(window.grab().save(dir + QStringLiteral("/screenshot-compare.png")));

        // The report of a restore with one refused row (not in docs/; for looking at it).
        ParameterEntry wrong = *file.find({ 0x6083, 0 });
        wrong.raw = u32(50000); // outside 1 .. 20000
        file.insert(wrong);
        compare->setFileSet(file, QStringLiteral("line-3-axis-2.dbp"));
        QTRY_VERIFY_WITH_TIMEOUT(!compare->isBusy() && compare->model()->selection().size() == 4,
                                 10000);
        QSignalSpy restored(compare, &ParamCompareView::restoreFinished);
        compare->startRestore();
        QVERIFY(restored.wait(10000));
        auto *report = compare->findChild<widgets::ParamCompareReport *>();
        QVERIFY(report);
        QCoreApplication::processEvents(); // the scroll and the repaint
        QVERIFY(report->grab().save(dir + QStringLiteral("/restore-report.png")));
        window.close();
    }
};

QTEST_MAIN(TestParamCompare)
#include "tst_paramcompare.moc"
