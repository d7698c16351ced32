#pragma once

#include "core/deviceconnection.h"
#include "parameters/parameterrunner.h"
#include "parameters/parameterset.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <optional>

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableView;

namespace db::widgets {

class ParamCompareFilter;
class ParamCompareModel;

// The parameter-set page: load a set from a file, read the same objects from the
// device, and show device / file / defaults side by side with a status per row and the counts;
// the user ticks the rows to restore. Loading and comparing only read; the device is written only
// by startRestore() (after the confirmation in restoreSelected()), and then only the ticked rows.
//
// Long steps (reading the device, restoring) run on the event loop with a progress bar and a
// Cancel button in the page; the result of a restore is shown in a non-modal report dialog and
// reported by restoreFinished().
class ParamCompareView : public QWidget
{
    Q_OBJECT
public:
    explicit ParamCompareView(QWidget *parent = nullptr);
    ~ParamCompareView() override;

    void setConnection(DeviceConnection *connection);
    DeviceConnection *connection() const { return m_connection; }

    // Loads a set and starts reading the device. Errors (corrupt, truncated, foreign file) are
    // shown in the page and returned; nothing is written and the previous set stays.
    Result<void> loadFile(const QString &path);
    void setFileSet(const ParameterSet &set, const QString &origin);
    bool hasFileSet() const { return m_file.has_value(); }

    ParamCompareModel *model() const { return m_model; }
    ParamCompareFilter *filter() const { return m_filter; }
    QTableView *table() const { return m_table; }
    // "3 unchanged, 2 changed, …" of the comparison shown.
    QString countsText() const;
    QString statusText() const;
    bool isBusy() const;
    // Whether the defaults take part in each row's status (they are always shown).
    void setCompareWithDefaults(bool on);
    void setOnlyDifferences(bool on);
    // Every row of the comparison (address, name, one value per side, unit, status) as CSV,
    // written atomically; fails when nothing was compared or the file cannot be written.
    Result<void> saveReportCsv(const QString &path) const;
    // The report for the record as a PDF (A4): the device's identity, the date, the file(s),
    // the counts and the rows that differ; written atomically. Fails like saveReportCsv().
    Result<void> saveReportPdf(const QString &path) const;
    // File against file: the set at `path` takes the device's place as the reference side (the
    // device is neither read nor written until Re-read Device). Needs a loaded set.
    Result<void> loadReferenceFile(const QString &path);
    bool comparesTwoFiles() const { return !m_referenceFile.isEmpty(); }
    void setStoreAfterRestore(bool on);
    std::optional<RestoreReport> lastReport() const { return m_lastReport; }
    // Asked before a set is compared with, and so may be restored to, another unit of the same
    // product (same vendor and product, another serial number): true goes on, false shows
    // nothing. The default asks with a message box; tests answer themselves.
    using Confirmation = std::function<bool(const QString &question)>;
    void setConfirmation(Confirmation confirm) { m_confirm = std::move(confirm); }
    // Why `device` is another unit than the one `file` was read from: both name a serial number
    // (1018h.4) and they differ; empty otherwise.
    static QString otherUnit(const ParameterSet &file, const ParameterSet &device);

public Q_SLOTS:
    // File dialog, then loadFile().
    void chooseFile();
    // Reads the device's values of the set's objects (and every storable object) again.
    void refreshDevice();
    // Asks for confirmation, then startRestore().
    void restoreSelected();
    // Writes the ticked rows now (no question asked), then reads the device again.
    void startRestore();
    void cancel();

Q_SIGNALS:
    void comparisonChanged();
    void restoreFinished(const db::RestoreReport &report);

private:
    void compare();
    static QString identityMismatch(const ParameterSet &file, const ParameterSet &device);
    bool askOtherUnit(const QString &question);
    void setBusy(const QString &what);
    void setIdle();
    void showStatus(const QString &text, const QColor &color = {});
    void updateActions();
    void onBackupFinished();
    void onRestoreFinished();

    QPointer<DeviceConnection> m_connection;
    QMetaObject::Connection m_stateConnection;
    std::optional<ParameterSet> m_file;
    QString m_fileOrigin;
    std::optional<ParameterSet> m_device; // or the reference file's set (m_referenceFile)
    QString m_referenceFile; // file name when m_device is a file, not the device
    std::unique_ptr<ParameterBackup> m_backup;
    std::unique_ptr<ParameterRestore> m_restore;
    std::optional<RestoreReport> m_lastReport;
    // The restore's outcome stays in the status line while the device is read again.
    QString m_restoreOutcome;
    bool m_restoreOk = true;
    Confirmation m_confirm;
    QString m_acceptedUnit; // the file and device serial numbers the user accepted to compare
    QString m_otherUnit; // otherUnit() of the comparison shown (accepted), else empty

    ParamCompareModel *m_model;
    ParamCompareFilter *m_filter;
    QLabel *m_fileLabel;
    QLabel *m_counts;
    QCheckBox *m_onlyDiff;
    QCheckBox *m_withDefaults;
    QCheckBox *m_hex;
    QTableView *m_table;
    QProgressBar *m_progress;
    QPushButton *m_cancel;
    QPushButton *m_load;
    QPushButton *m_reread;
    QPushButton *m_selectDiff;
    QPushButton *m_selectNone;
    QCheckBox *m_store;
    QPushButton *m_restoreButton;
    QLabel *m_status;
};

} // namespace db::widgets
