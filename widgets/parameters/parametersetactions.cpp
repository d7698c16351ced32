#include "parametersetactions.h"

#include "description/dcfwriter.h"

#include <QAction>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QMessageBox>
#include <QPointer>
#include <QProgressDialog>
#include <QPushButton>

namespace db::widgets {

namespace {
constexpr int kListedFailures = 5; // failed objects named in the message; the file has them all
}

ParameterSetActions::ParameterSetActions(QWidget *dialogParent, QObject *parent)
    : QObject(parent)
    , m_dialogParent(dialogParent)
    , m_backUp(new QAction(tr("&Back Up…"), this))
    , m_compare(new QAction(tr("&Compare / Restore…"), this))
    , m_store(new QAction(tr("&Store Permanently"), this))
    , m_factory(new QAction(tr("Restore &Factory Defaults…"), this))
    , m_exportDcf(new QAction(tr("Export &DCF…"), this))
{
    m_backUp->setObjectName(QStringLiteral("paramBackUp"));
    m_compare->setObjectName(QStringLiteral("paramCompare"));
    m_store->setObjectName(QStringLiteral("paramStore"));
    m_factory->setObjectName(QStringLiteral("paramFactory"));
    m_exportDcf->setObjectName(QStringLiteral("paramExportDcf"));
    m_backUp->setToolTip(tr("Save every storable parameter of the device to a file"));
    m_compare->setToolTip(tr("Load a parameter set and compare it with the device and the "
                             "defaults; restore selected rows"));
    m_store->setToolTip(tr("Save the device's current parameters in its non-volatile memory "
                           "(1010h \"save\")"));
    m_factory->setToolTip(tr("Reset every parameter to the factory value (1011h \"load\")"));
    m_exportDcf->setToolTip(tr("Write a CiA 306 device configuration file with the device's "
                               "current values"));
    connect(m_backUp, &QAction::triggered, this, &ParameterSetActions::backUp);
    connect(m_compare, &QAction::triggered, this, &ParameterSetActions::compareRequested);
    connect(m_store, &QAction::triggered, this, &ParameterSetActions::store);
    connect(m_factory, &QAction::triggered, this, &ParameterSetActions::restoreFactoryDefaults);
    connect(m_exportDcf, &QAction::triggered, this, &ParameterSetActions::exportDcf);
    updateActions();
}

ParameterSetActions::~ParameterSetActions()
{
    disconnect(m_stateConnection);
    if (m_backup)
        disconnect(m_backup.get(), nullptr, this, nullptr);
}

QList<QAction *> ParameterSetActions::actions() const
{
    return { m_backUp, m_compare, m_store, m_factory, m_exportDcf };
}

void ParameterSetActions::setConnection(DeviceConnection *connection)
{
    if (connection == m_connection)
        return;
    cancel();
    disconnect(m_stateConnection);
    m_connection = connection;
    if (connection) {
        m_stateConnection = connect(connection, &DeviceConnection::stateChanged, this,
                                    &ParameterSetActions::updateActions);
    }
    updateActions();
}

void ParameterSetActions::updateActions()
{
    const bool ready = m_connection && m_connection->isConnected() && !isBusy();
    const bool canStore =
        ready && (m_connection->capabilities() & DeviceConnection::Capability::StoreNonVolatile);
    m_backUp->setEnabled(ready);
    m_exportDcf->setEnabled(ready);
    m_store->setEnabled(canStore);
    m_factory->setEnabled(canStore);
    m_compare->setEnabled(true); // a file can be looked at without a device
}

QString ParameterSetActions::suggestedName(const QString &suffix) const
{
    QString product = m_connection ? m_connection->dictionary().identity.productName : QString();
    product.replace(QLatin1Char(' '), QLatin1Char('_'));
    if (product.isEmpty())
        product = QStringLiteral("device");
    return QDir::home().filePath(
        QStringLiteral("%1-%2.%3")
            .arg(product, QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm")),
                 suffix));
}

void ParameterSetActions::backUp()
{
    const QString path = QFileDialog::getSaveFileName(m_dialogParent, tr("Back Up Parameters"),
                                                      suggestedName(QStringLiteral("dbp")),
                                                      tr("Parameter sets (*.dbp);;All files (*)"));
    if (!path.isEmpty())
        backUpTo(path);
}

void ParameterSetActions::backUpTo(const QString &path)
{
    runBackup(tr("Backing up parameters…"), [this, path](const ParameterBackup &backup) {
        const auto result = backup.result();
        if (!result) {
            // Never replace a file with less than a complete set: what was read goes beside
            // it, with a comment line per object that was not.
            const QString partial = path + QStringLiteral(".partial");
            QStringList comments { tr("partial backup: %1 of %2 objects could not be read; not "
                                      "a complete set")
                                       .arg(backup.failures().size())
                                       .arg(backup.objectCount()) };
            for (const QString &line : backup.warnings())
                comments.append(QStringLiteral("failed ") + line);
            const auto saved = backup.partialSet().save(partial, comments);
            const QStringList failed = backup.warnings();
            report(tr("Backup incomplete, %1 not written: %2\n%3\nFailed: %4%5")
                       .arg(QDir::toNativeSeparators(path), result.error().toString(),
                            saved ? tr("The %n parameter(s) read and the failures are in %1.",
                                       nullptr, backup.partialSet().size())
                                        .arg(QDir::toNativeSeparators(partial))
                                  : saved.error().toString(),
                            failed.mid(0, kListedFailures).join(QStringLiteral("; ")),
                            failed.size() > kListedFailures
                                ? tr(" and %n more", nullptr, int(failed.size() - kListedFailures))
                                : QString()),
                   false);
            Q_EMIT backupFinished(false, path);
            return;
        }
        const auto saved = result->save(path);
        if (!saved) {
            report(tr("Backup not saved: %1").arg(saved.error().toString()), false);
            Q_EMIT backupFinished(false, path);
            return;
        }
        report(tr("Backed up %n parameter(s) to %1", nullptr, result->size())
                   .arg(QDir::toNativeSeparators(path)),
               true);
        Q_EMIT backupFinished(true, path);
    });
}

void ParameterSetActions::exportDcf()
{
    const QString path = QFileDialog::getSaveFileName(
        m_dialogParent, tr("Export DCF"), suggestedName(QStringLiteral("dcf")),
        tr("Device configuration files (*.dcf);;All files (*)"));
    if (!path.isEmpty())
        exportDcfTo(path);
}

void ParameterSetActions::exportDcfTo(const QString &path)
{
    runBackup(tr("Reading parameters for the DCF…"), [this, path](const ParameterBackup &backup) {
        // A DCF that silently lacks values is as bad as a partial backup: none is written.
        const auto result = backup.result();
        if (!result) {
            report(tr("DCF not written: %1").arg(result.error().toString()), false);
            return;
        }
        const ParameterSet &set = result.value();
        DcfCommissioning commissioning;
        const ConnectionUri &uri = m_connection ? m_connection->uri() : ConnectionUri();
        if (auto node = uri.queryInt(QStringLiteral("node"), 1, 127);
            node && uri.hasQuery(QStringLiteral("node")))
            commissioning.nodeId = quint8(node.value());
        const ObjectDictionary dictionary =
            m_connection ? m_connection->dictionary() : ObjectDictionary();
        const auto written = writeDcf(path, dictionary, set.values(), commissioning);
        report(written ? tr("Exported the DCF with %n value(s) to %1", nullptr, set.size())
                             .arg(QDir::toNativeSeparators(path))
                       : tr("DCF not written: %1").arg(written.error().toString()),
               written.ok());
    });
}

void ParameterSetActions::runBackup(const QString &title,
                                    std::function<void(const ParameterBackup &)> done)
{
    if (!m_connection || !m_connection->isConnected()) {
        report(tr("Not connected"), false);
        Q_EMIT backupFinished(false, QString());
        return;
    }
    if (isBusy())
        return;
    m_backup = std::make_unique<ParameterBackup>(m_connection);
    m_progress = new QProgressDialog(title, tr("Cancel"), 0, 0, m_dialogParent);
    m_progress->setWindowTitle(tr("Parameters"));
    m_progress->setMinimumDuration(0);
    m_progress->setAttribute(Qt::WA_DeleteOnClose);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    connect(m_progress, &QProgressDialog::canceled, this, &ParameterSetActions::cancel);
    connect(m_backup.get(), &ParameterBackup::progress, m_progress,
            [this](int doneCount, int total) {
                m_progress->setMaximum(total);
                m_progress->setValue(doneCount);
            });
    connect(m_backup.get(), &ParameterBackup::finished, this, [this, done] {
        // finished() may come from inside cancel(): delete the runner from the event loop.
        ParameterBackup *backup = m_backup.release();
        backup->deleteLater();
        if (m_progress)
            m_progress->close();
        updateActions();
        if (backup->error().kind() == Error::Kind::Cancelled) {
            report(tr("Backup cancelled; nothing was saved"), false);
            Q_EMIT backupFinished(false, QString());
            return;
        }
        done(*backup);
    });
    updateActions();
    m_progress->open();
    m_backup->start();
}

void ParameterSetActions::cancel()
{
    if (m_backup && m_backup->isRunning())
        m_backup->cancel();
}

void ParameterSetActions::store()
{
    if (!m_connection)
        return;
    const auto answer = QMessageBox::question(
        m_dialogParent, tr("Store Parameters"),
        tr("Store the current parameters of %1 permanently (1010h \"save\")?\n\nThe values the "
           "device holds now become its power-up values.")
            .arg(m_connection->uri().toString()),
        QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        storeNow();
}

void ParameterSetActions::storeNow()
{
    if (!m_connection || !m_connection->isConnected() || isBusy())
        return;
    Reply *reply = m_connection->storeNonVolatile();
    if (m_changeLog) {
        ChangeLog::Entry e;
        e.device = m_connection->uri().toString();
        e.kind = ChangeLog::Kind::Store;
        e.object = tr("all parameters");
        m_changeLog->track(e, reply);
    }
    connect(reply, &Reply::finished, this,
            [this, reply, connection = QPointer<DeviceConnection>(m_connection),
             device = m_connection->uri().toString()] {
                if (reply->ok() && m_changeLog)
                    m_changeLog->markStored(device);
                if (reply->ok() && connection)
                    Q_EMIT storedPermanently(connection);
            });
    writeSignature(reply, tr("Parameters stored permanently"));
}

void ParameterSetActions::restoreFactoryDefaultsNow()
{
    if (!m_connection || !m_connection->isConnected() || isBusy())
        return;
    Reply *reply = m_connection->restoreFactoryDefaults();
    if (m_changeLog) {
        ChangeLog::Entry e;
        e.device = m_connection->uri().toString();
        e.kind = ChangeLog::Kind::Restore;
        e.object = tr("factory defaults");
        m_changeLog->track(e, reply);
    }
    writeSignature(reply,
                   tr("Factory defaults restored (1011h); they take effect after the next "
                      "reset or power cycle"));
}

void ParameterSetActions::writeSignature(Reply *reply, const QString &what)
{
    reply->setParent(this);
    m_pendingWrite = true;
    updateActions();
    connect(reply, &Reply::finished, this, [this, reply, what] {
        reply->deleteLater();
        m_pendingWrite = false;
        updateActions();
        report(reply->ok() ? what : tr("Refused by the device: %1").arg(reply->error().toString()),
               reply->ok());
    });
}

void ParameterSetActions::report(const QString &text, bool ok)
{
    Q_EMIT message(text, ok);
    if (!ok && m_dialogParent && m_dialogParent->isVisible()) {
        auto *box = new QMessageBox(QMessageBox::Warning, tr("Parameters"), text, QMessageBox::Ok,
                                    m_dialogParent);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    }
}

void ParameterSetActions::restoreFactoryDefaults()
{
    if (!m_connection)
        return;
    const DeviceIdentity &id = m_connection->dictionary().identity;
    const bool movingCap = id.productName.contains(QLatin1String("MovingCap"), Qt::CaseInsensitive);
    QString lost = tr("Every parameter of %1 returns to its factory value: positions, limits, "
                      "velocities, I/O functions, PDO mappings and communication settings you "
                      "changed are lost.")
                       .arg(m_connection->uri().toString());
    if (movingCap)
        lost += QLatin1Char(' ')
            + tr("On a MovingCap this also deletes the Python script stored "
                 "in the drive.");
    QMessageBox box(QMessageBox::Warning, tr("Restore Factory Defaults"),
                    tr("Restore the factory defaults (1011h \"load\")?"), QMessageBox::Cancel,
                    m_dialogParent);
    box.setInformativeText(lost + QStringLiteral("\n\n")
                           + tr("This cannot be undone from drivebench unless you have a backup."));
    QPushButton *backupFirst = box.addButton(tr("Back Up First…"), QMessageBox::AcceptRole);
    QPushButton *anyway =
        box.addButton(tr("Restore Defaults Without Backup"), QMessageBox::DestructiveRole);
    box.setDefaultButton(backupFirst);
    box.exec();
    if (box.clickedButton() == anyway) {
        restoreFactoryDefaultsNow();
    } else if (box.clickedButton() == backupFirst) {
        const QString path = QFileDialog::getSaveFileName(
            m_dialogParent, tr("Back Up Before Factory Defaults"),
            suggestedName(QStringLiteral("dbp")), tr("Parameter sets (*.dbp);;All files (*)"));
        if (path.isEmpty())
            return;
        // The defaults are restored only after the backup has been saved.
        auto *once = new QObject(this);
        connect(this, &ParameterSetActions::backupFinished, once, [this, once](bool ok) {
            once->deleteLater();
            if (ok)
                restoreFactoryDefaultsNow();
            else
                report(tr("Factory defaults not restored: the backup did not succeed"), false);
        });
        backUpTo(path);
    }
}

} // namespace db::widgets
