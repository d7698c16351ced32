#pragma once

#include "core/changelog.h"
#include "core/deviceconnection.h"
#include "parameters/parameterrunner.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>

class QAction;
class QProgressDialog;
class QWidget;

namespace db::widgets {

// The "Parameters" commands of the GUI as actions for a menu and the editor's
// tool row: Back Up…, Compare… (compareRequested; the page does the rest), Store Permanently
// (1010h), Restore Factory Defaults… (1011h, after a strong confirmation that offers a backup
// first) and Export DCF…. Long runs show a progress dialog with Cancel; outcomes are reported by
// message() (and errors also in a message box). The actions are enabled while the connection is
// up and nothing else runs.
class ParameterSetActions : public QObject
{
    Q_OBJECT
public:
    // dialogParent: the window the dialogs belong to (not owned).
    explicit ParameterSetActions(QWidget *dialogParent, QObject *parent = nullptr);
    ~ParameterSetActions() override;

    void setConnection(DeviceConnection *connection);
    // Stores and factory-default restores are recorded there (null: none).
    void setChangeLog(ChangeLog *log) { m_changeLog = log; }

    QAction *backUpAction() const { return m_backUp; }
    QAction *compareAction() const { return m_compare; }
    QAction *storeAction() const { return m_store; }
    QAction *factoryDefaultsAction() const { return m_factory; }
    QAction *exportDcfAction() const { return m_exportDcf; }
    QList<QAction *> actions() const;

    bool isBusy() const { return m_backup != nullptr || m_pendingWrite; }

public Q_SLOTS:
    // With file dialogs / confirmations.
    void backUp();
    void store();
    void restoreFactoryDefaults();
    void exportDcf();

    // Without asking (tests, and after the user confirmed): run, then report with message().
    // Only a complete set is written to path; when any object could not be read, path stays
    // as it was, the objects read go to path + ".partial" with a comment line per failure,
    // and message() names the failed objects (backupFinished(false, path)).
    void backUpTo(const QString &path);
    void exportDcfTo(const QString &path);
    void storeNow();
    void restoreFactoryDefaultsNow();
    void cancel();

Q_SIGNALS:
    void compareRequested();
    // Outcome of every command, for the status bar and log.
    void message(const QString &text, bool ok);
    void backupFinished(bool ok, const QString &path);
    // The device took "save" (1010h): what was written to it survives a power cycle.
    void storedPermanently(db::DeviceConnection *connection);

private:
    // Reads every storable object with a progress dialog, then calls done with the finished
    // runner, complete or not (not called on cancel, which is reported here).
    void runBackup(const QString &title, std::function<void(const ParameterBackup &)> done);
    void writeSignature(Reply *reply, const QString &what);
    void report(const QString &text, bool ok);
    void updateActions();
    QString suggestedName(const QString &suffix) const;

    QWidget *m_dialogParent;
    QPointer<DeviceConnection> m_connection;
    QPointer<ChangeLog> m_changeLog;
    QMetaObject::Connection m_stateConnection;
    std::unique_ptr<ParameterBackup> m_backup;
    QPointer<QProgressDialog> m_progress;
    bool m_pendingWrite = false;

    QAction *m_backUp;
    QAction *m_compare;
    QAction *m_store;
    QAction *m_factory;
    QAction *m_exportDcf;
};

} // namespace db::widgets
