// The change log: what the user changed on the devices this session, fed by every widget that
// changes a device, and each finished change as a line in the log console (a failed one also
// in the status bar).
#include "mainwindow.h"

#include "core/changelog.h"
#include "core/valuecodec.h"
#include "parameters/parameterrunner.h"
#include "widgets/canopen/networkview.h"
#include "widgets/canopen/nodelist.h"
#include "widgets/common/logconsole.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/odeditor/objectaccessbox.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/parameters/paramcomparemodel.h"
#include "widgets/parameters/paramcompareview.h"
#include "widgets/parameters/parametersetactions.h"

#include <QStatusBar>

namespace db::gui {

namespace {
constexpr int kFailureMessageMs = 20000;
}

void MainWindow::createChangeLog()
{
    m_odEditor->setChangeLog(m_changeLog);
    m_objectAccess->setChangeLog(m_changeLog);
    m_jogPanel->setChangeLog(m_changeLog);
    m_paramActions->setChangeLog(m_changeLog);

    m_networkView->setChangeLog(m_changeLog);
    m_nodeList->setChangeLog(m_changeLog); // the node dock sends NMT commands as the page does

    connect(m_compareView, &widgets::ParamCompareView::restoreFinished, this,
            [this](const RestoreReport &report) {
                const QString device = m_compareView->connection()
                    ? m_compareView->connection()->uri().toString()
                    : QString();
                const bool canStore = m_compareView->connection()
                    && m_compareView->connection()->capabilities().testFlag(
                        DeviceConnection::Capability::StoreNonVolatile);
                // The device's values before the restore: the comparison it was chosen from
                // (its first side is the device) is refreshed only after this signal.
                QHash<ObjectAddress, QString> before;
                for (const CompareRow &r : m_compareView->model()->comparison().rows) {
                    if (!r.values.isEmpty() && r.values.first().isValid())
                        before.insert(r.address, r.valueText(0));
                }
                for (const RestoreRow &row : report.rows) {
                    if (row.outcome == RestoreOutcome::Skipped)
                        continue;
                    ChangeLog::Entry e;
                    e.device = device;
                    e.kind = ChangeLog::Kind::Restore;
                    e.object = report.addressFormat->format(row.address);
                    if (!row.name.isEmpty())
                        e.object += QLatin1Char(' ') + row.name;
                    e.oldValue = before.value(row.address);
                    e.newValue = codec::toText(row.type, row.value);
                    const bool ok = row.outcome == RestoreOutcome::Verified
                        || row.outcome == RestoreOutcome::Written;
                    e.outcome = ok ? ChangeLog::Outcome::Ok : ChangeLog::Outcome::Failed;
                    e.message = ok
                        ? QString()
                        : restoreOutcomeName(row.outcome) + QStringLiteral(": ") + row.reason;
                    e.storable = canStore;
                    e.stored = report.stored;
                    m_changeLog->add(e);
                }
                if (report.storeRequested) {
                    ChangeLog::Entry e;
                    e.device = device;
                    e.kind = ChangeLog::Kind::Store;
                    e.object = tr("all parameters");
                    e.outcome = report.stored ? ChangeLog::Outcome::Ok : ChangeLog::Outcome::Failed;
                    e.message = report.stored ? QString() : report.storeReason;
                    m_changeLog->add(e);
                    if (report.stored)
                        m_changeLog->markStored(device);
                }
            });

    // One line per change once its outcome is known; entries made finished count at once.
    const auto logFinished = [this](int index) {
        const ChangeLog::Entry &e = m_changeLog->entries().at(index);
        if (e.outcome == ChangeLog::Outcome::Pending || m_logged.contains(e.id))
            return;
        m_logged.insert(e.id);
        if (m_logged.size() > ChangeLog::kMaxEntries) { // forget ids the log has dropped
            const int first = m_changeLog->entries().first().id;
            m_logged.removeIf([first](int id) { return id < first; });
        }
        m_log->change(ChangeLog::summary(e));
        // A command that failed or got no answer is said where the user looks, not only in
        // the log: the status bar (the panel that sent it says so too).
        if (e.outcome == ChangeLog::Outcome::Failed)
            statusBar()->showMessage(ChangeLog::summary(e), kFailureMessageMs);
    };
    connect(m_changeLog, &ChangeLog::entryAdded, this, logFinished);
    connect(m_changeLog, &ChangeLog::entryChanged, this, logFinished);
}

} // namespace db::gui
