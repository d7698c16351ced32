// ParamCompareView, part 2: reading the device, comparing and restoring.

#include "paramcomparemodel.h"
#include "paramcomparereport.h"
#include "paramcompareview.h"
#include "widgets/common/widgetstyle.h"

#include <QCheckBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableView>

namespace db::widgets {

namespace {
constexpr ObjectAddress kVendorId(0x1018, 1);
constexpr ObjectAddress kProductCode(0x1018, 2);
constexpr ObjectAddress kSerialNumber(0x1018, 4);

QString hex32(quint32 v)
{
    return QStringLiteral("%1").arg(v, 8, 16, QLatin1Char('0')).toUpper() + QLatin1Char('h');
}
} // namespace

// Why `file` must not be compared with what was read from the device: the device reported
// another vendor or product (1018h) than the file names; empty when they agree or one side
// does not know.
QString ParamCompareView::identityMismatch(const ParameterSet &file, const ParameterSet &device)
{
    const auto reported = [&device](ObjectAddress a) -> std::optional<quint32> {
        const ParameterEntry *e = device.find(a);
        return e ? std::optional<quint32>(quint32(e->raw.toULongLong())) : std::nullopt;
    };
    const auto vendor = reported(kVendorId);
    const auto product = reported(kProductCode);
    const bool vendorDiffers = vendor && file.vendorIdKnown && file.identity.vendorId != 0
        && *vendor != file.identity.vendorId;
    const bool productDiffers = product && file.productCodeKnown && file.identity.productCode != 0
        && *product != file.identity.productCode;
    if (!vendorDiffers && !productDiffers)
        return {};
    return tr("Not compared: the file is from vendor %1, product %2, but the device reports "
              "vendor %3, product %4 (1018h). Connect the device the set belongs to.")
        .arg(hex32(file.identity.vendorId), hex32(file.identity.productCode),
             vendor ? hex32(*vendor) : tr("unknown"), product ? hex32(*product) : tr("unknown"));
}

QString ParamCompareView::otherUnit(const ParameterSet &file, const ParameterSet &device)
{
    const ParameterEntry *reported = device.find(kSerialNumber);
    if (file.serialNumber.isEmpty() || !reported)
        return {};
    const QString serial = ParameterSet::identityNumber(quint32(reported->raw.toULongLong()));
    if (serial.compare(file.serialNumber, Qt::CaseInsensitive) == 0)
        return {};
    return tr("The file was read from another unit of this product: serial number %1, this "
              "device reports %2 (1018h.4). Values such as calibrations and offsets belong to "
              "one unit.")
        .arg(file.serialNumber, serial);
}

void ParamCompareView::refreshDevice()
{
    if (!m_file || isBusy())
        return;
    if (!m_referenceFile.isEmpty()) { // back from file-against-file to the device
        m_referenceFile.clear();
        m_device.reset();
        compare();
    }
    if (!m_connection || !m_connection->isConnected()) {
        showStatus(tr("Not connected: the device column stays empty until a device is "
                      "connected."),
                   style::warningColor());
        return;
    }
    // The set's objects and every storable object, so that objects missing from the file show.
    QList<ObjectAddress> addresses = m_file->addresses();
    for (const ObjectDef &def : m_connection->dictionary().objects()) {
        if (def.storable && def.readable() && !addresses.contains(def.address))
            addresses.append(def.address);
    }
    // The device's identity, checked against the file's before anything is compared.
    for (ObjectAddress a : { kVendorId, kProductCode, kSerialNumber }) {
        const ObjectDef *def = m_connection->dictionary().find(a);
        if (def && def->readable() && !addresses.contains(a))
            addresses.append(a);
    }
    std::sort(addresses.begin(), addresses.end());
    m_backup = std::make_unique<ParameterBackup>(m_connection);
    m_backup->setAddresses(addresses);
    connect(m_backup.get(), &ParameterBackup::progress, m_progress, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
    });
    connect(m_backup.get(), &ParameterBackup::finished, this, &ParamCompareView::onBackupFinished);
    setBusy(tr("Reading %n object(s) from the device…", nullptr, int(addresses.size())));
    m_backup->start();
}

void ParamCompareView::onBackupFinished()
{
    // A comparison may show a partly read device: the objects that could not be read show as
    // missing on the device side, and the status names them. A run that stopped shows nothing.
    const Error stopped = m_backup->error();
    const QStringList warnings = m_backup->warnings();
    const ParameterSet read = m_backup->partialSet();
    setIdle();
    if (stopped.isError() || read.isEmpty()) {
        m_restoreOutcome.clear();
        const Error error = stopped.isError() ? stopped : m_backup->result().error();
        showStatus(tr("Reading the device failed: %1").arg(error.toString()),
                   error.kind() == Error::Kind::Cancelled ? style::warningColor()
                                                          : style::errorColor());
        return;
    }
    m_device = read;
    compare();
    if (m_model->comparison().rows.isEmpty()) {
        m_restoreOutcome.clear();
        return; // compare() said why nothing is shown (another device, unit or address format)
    }
    if (!m_restoreOutcome.isEmpty()) {
        showStatus(std::exchange(m_restoreOutcome, {}) + QLatin1Char(' ')
                       + tr("The comparison shows the device after the restore."),
                   m_restoreOk ? style::okColor() : style::errorColor());
    } else if (!m_otherUnit.isEmpty()) {
        showStatus(tr("Compared %1 with another unit. %2 Nothing has been written.")
                       .arg(m_fileOrigin, m_otherUnit),
                   style::warningColor());
    } else if (warnings.isEmpty()) {
        showStatus(tr("Compared %1 with the device. Nothing has been written.").arg(m_fileOrigin));
    } else {
        showStatus(tr("Compared; %n object(s) could not be read: %1", nullptr, int(warnings.size()))
                       .arg(warnings.mid(0, 3).join(QStringLiteral("; "))),
                   style::warningColor());
    }
}

void ParamCompareView::compare()
{
    if (!m_file) {
        m_model->setComparison({}, {}, {});
        m_counts->clear();
        updateActions();
        return;
    }
    const ObjectDictionary dictionary =
        m_connection ? m_connection->dictionary() : ObjectDictionary();
    // Every side is in the device's address format; a file in another one holds other objects
    // under the same addresses and is not compared.
    const AddressFormat *format =
        m_connection ? &m_connection->addressFormat() : m_file->addressFormat;
    ParameterSet defaults = ParameterSet::defaults(dictionary);
    defaults.addressFormat = format;
    ParameterSet device = m_device.value_or(ParameterSet());
    if (!m_device)
        device.addressFormat = format;
    if (m_device && m_referenceFile.isEmpty()) {
        // Never compared (or restored) against another kind of device without saying so.
        if (const QString why = identityMismatch(*m_file, device); !why.isEmpty()) {
            m_model->setComparison({}, {}, {});
            m_counts->clear();
            showStatus(why, style::errorColor());
            updateActions();
            return;
        }
        // Another unit of the same product: only once the user said so.
        m_otherUnit = otherUnit(*m_file, device);
        if (!m_otherUnit.isEmpty()) {
            const QString key = m_file->serialNumber + QLatin1Char('|')
                + QString::number(device.find(kSerialNumber)->raw.toULongLong());
            if (key != m_acceptedUnit) {
                const QString question =
                    m_otherUnit + QLatin1Char('\n') + tr("Compare with this unit anyway?");
                if (!(m_confirm ? m_confirm(question) : askOtherUnit(question))) {
                    m_model->setComparison({}, {}, {});
                    m_counts->clear();
                    showStatus(tr("Not compared: %1").arg(m_otherUnit), style::warningColor());
                    m_otherUnit.clear();
                    updateActions();
                    return;
                }
                m_acceptedUnit = key;
            }
        }
        for (ObjectAddress a : { kVendorId, kProductCode, kSerialNumber }) {
            if (!m_file->contains(a))
                device.remove(a); // read for the check only
        }
    } else {
        m_otherUnit.clear();
    }
    QList<ParameterSet> sides { device, *m_file };
    QStringList names { m_referenceFile.isEmpty() ? tr("Device") : m_referenceFile, tr("File") };
    if (auto same = checkSameAddressFormat(sides, names); !same) {
        m_model->setComparison({}, {}, {});
        m_counts->clear();
        showStatus(same.error().message(), style::errorColor());
        updateActions();
        return;
    }
    if (m_withDefaults->isChecked()) {
        sides.append(defaults);
        names.append(tr("Defaults"));
    }
    const ParameterComparison comparison =
        compareParameterSets(sides, names, m_connection ? &dictionary : nullptr);
    m_model->setComparison(comparison, defaults, dictionary);

    QStringList chips;
    for (CompareStatus s : { CompareStatus::Changed, CompareStatus::Unchanged,
                             CompareStatus::Missing, CompareStatus::Unknown }) {
        chips.append(QStringLiteral("<span style='color:%1'>&#9679;</span> <b>%2</b> %3")
                         .arg(compareStatusColor(s).name())
                         .arg(comparison.count(s))
                         .arg(compareStatusName(s)));
    }
    m_counts->setText(chips.join(QStringLiteral(" &nbsp;&nbsp; ")));
    m_counts->setToolTip(comparison.countsText());
    updateActions();
    Q_EMIT comparisonChanged();
}

void ParamCompareView::startRestore()
{
    const QList<ObjectAddress> rows = m_model->selection();
    if (!m_file || rows.isEmpty() || isBusy() || !m_connection || !m_connection->isConnected())
        return;
    m_restore = std::make_unique<ParameterRestore>(m_connection);
    m_restore->setParameterSet(*m_file);
    m_restore->setSelection(rows);
    m_restore->setVerify(true);
    m_restore->setStoreAfterwards(m_store->isChecked());
    connect(m_restore.get(), &ParameterRestore::progress, m_progress, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
    });
    connect(m_restore.get(), &ParameterRestore::finished, this,
            &ParamCompareView::onRestoreFinished);
    setBusy(tr("Writing %n value(s)…", nullptr, int(rows.size())));
    m_restore->start();
}

void ParamCompareView::onRestoreFinished()
{
    const RestoreReport report = m_restore->report();
    m_lastReport = report;
    setIdle();
    const int failed =
        report.count(RestoreOutcome::Failed) + report.count(RestoreOutcome::Mismatch);
    const int written =
        report.count(RestoreOutcome::Verified) + report.count(RestoreOutcome::Written);
    m_restoreOk = report.succeeded();
    m_restoreOutcome = report.succeeded()
        ? tr("Restored %n value(s)%1.", nullptr, written)
              .arg(report.stored ? tr(" and stored them permanently") : QString())
        : tr("Restore incomplete: %1 written, %2 failed, %3 skipped (see the report).")
              .arg(written)
              .arg(failed)
              .arg(report.count(RestoreOutcome::Skipped));
    showStatus(m_restoreOutcome, m_restoreOk ? style::okColor() : style::errorColor());
    auto *dialog = new ParamCompareReport(report, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    Q_EMIT restoreFinished(report);
    refreshDevice();
}

void ParamCompareView::cancel()
{
    if (m_backup && m_backup->isRunning())
        m_backup->cancel();
    if (m_restore && m_restore->isRunning())
        m_restore->cancel();
}

void ParamCompareView::setBusy(const QString &what)
{
    m_progress->setRange(0, 0);
    m_progress->show();
    m_cancel->show();
    if (m_restoreOutcome.isEmpty())
        showStatus(what);
    else
        showStatus(m_restoreOutcome + QLatin1Char(' ') + what,
                   m_restoreOk ? style::okColor() : style::errorColor());
    updateActions();
}

void ParamCompareView::setIdle()
{
    m_progress->hide();
    m_cancel->hide();
    updateActions();
}

void ParamCompareView::updateActions()
{
    const bool busy = isBusy();
    const bool connected = m_connection && m_connection->isConnected();
    const int selected = int(m_model->selection().size());
    m_load->setEnabled(!busy);
    m_reread->setEnabled(!busy && connected && m_file);
    m_selectDiff->setEnabled(!busy && m_file);
    m_selectNone->setEnabled(!busy && selected > 0);
    // Restoring writes the device: never while the reference side is another file.
    m_restoreButton->setEnabled(!busy && connected && selected > 0 && m_device
                                && m_referenceFile.isEmpty());
    m_restoreButton->setText(selected > 0 ? tr("&Restore %n Selected…", nullptr, selected)
                                          : tr("&Restore Selected…"));
    m_store->setEnabled(
        !busy && connected
        && (m_connection->capabilities() & DeviceConnection::Capability::StoreNonVolatile));
}

} // namespace db::widgets
