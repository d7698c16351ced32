#pragma once

#include "parameters/parameterrunner.h"

#include <QDialog>

class QTreeWidget;

namespace db::widgets {

// The outcome of a restore: counts, then every selected row with what happened
// to it (verified, written, failed with the device's reason, mismatch, skipped) and the result of
// the permanent store. Failed rows come first. "Copy" puts RestoreReport::summary() on the
// clipboard for a ticket or a commissioning record.
class ParamCompareReport : public QDialog
{
    Q_OBJECT
public:
    explicit ParamCompareReport(const RestoreReport &report, QWidget *parent = nullptr);

    QTreeWidget *rows() const { return m_rows; }

private:
    RestoreReport m_report;
    QTreeWidget *m_rows;
};

} // namespace db::widgets
