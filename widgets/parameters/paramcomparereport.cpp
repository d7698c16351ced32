#include "paramcomparereport.h"

#include "widgets/common/widgetstyle.h"

#include "core/printable.h"

#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace db::widgets {

namespace {
QColor outcomeColor(RestoreOutcome outcome)
{
    switch (outcome) {
    case RestoreOutcome::Verified:
    case RestoreOutcome::Written:
        return style::okColor();
    case RestoreOutcome::Failed:
    case RestoreOutcome::Mismatch:
        return style::errorColor();
    case RestoreOutcome::Skipped:
        return style::inactiveColor();
    }
    return {};
}

int severity(RestoreOutcome outcome)
{
    switch (outcome) {
    case RestoreOutcome::Failed:
        return 0;
    case RestoreOutcome::Mismatch:
        return 1;
    case RestoreOutcome::Skipped:
        return 2;
    default:
        return 3;
    }
}
} // namespace

ParamCompareReport::ParamCompareReport(const RestoreReport &report, QWidget *parent)
    : QDialog(parent)
    , m_report(report)
    , m_rows(new QTreeWidget(this))
{
    setObjectName(QStringLiteral("restoreReport"));
    setWindowTitle(report.succeeded() ? tr("Restore Report") : tr("Restore Report — Incomplete"));
    const int written =
        report.count(RestoreOutcome::Verified) + report.count(RestoreOutcome::Written);
    auto *headline = new QLabel(this);
    headline->setTextFormat(Qt::RichText);
    headline->setWordWrap(true);
    QString text = tr("<b>%1 written</b> (%2 verified by reading back), <b>%3 failed</b>, "
                      "%4 mismatched, %5 skipped.")
                       .arg(written)
                       .arg(report.count(RestoreOutcome::Verified))
                       .arg(report.count(RestoreOutcome::Failed))
                       .arg(report.count(RestoreOutcome::Mismatch))
                       .arg(report.count(RestoreOutcome::Skipped));
    if (report.error.isError())
        text +=
            QStringLiteral("<br>") + tr("Stopped: %1").arg(report.error.toString().toHtmlEscaped());
    if (report.storeRequested) {
        text += QStringLiteral("<br>")
            + (report.stored ? tr("Stored permanently (1010h).")
                             : tr("Not stored permanently: %1")
                                   .arg(printable(report.storeReason).toHtmlEscaped()));
    }
    for (const QString &note : report.notes)
        text += QStringLiteral("<br>") + printable(note).toHtmlEscaped();
    headline->setText(text);
    style::setTextColor(headline, report.succeeded() ? QColor() : style::errorColor());

    m_rows->setObjectName(QStringLiteral("reportRows"));
    m_rows->setRootIsDecorated(false);
    m_rows->setAlternatingRowColors(true);
    m_rows->setHeaderLabels(
        { tr("Outcome"), tr("Index:Sub"), tr("Name"), tr("Value"), tr("Reason") });
    QList<RestoreRow> rows = report.rows;
    std::stable_sort(rows.begin(), rows.end(), [](const RestoreRow &a, const RestoreRow &b) {
        return severity(a.outcome) < severity(b.outcome);
    });
    for (const RestoreRow &r : rows) {
        auto *item = new QTreeWidgetItem(m_rows);
        item->setText(0, restoreOutcomeName(r.outcome));
        item->setForeground(0, outcomeColor(r.outcome));
        item->setText(1, r.address.toString());
        item->setFont(1, style::monospaceFont());
        // Name, value and reason quote the file and the device: escaped, one line each.
        item->setText(2, printable(r.name));
        item->setText(3, printable(codec::toText(r.type, r.value)));
        item->setFont(3, style::monospaceFont());
        item->setText(4, printable(r.reason));
        item->setToolTip(4, printable(r.reason));
        item->setData(0, Qt::UserRole, int(r.outcome));
    }
    m_rows->header()->resizeSection(0, 90);
    m_rows->header()->resizeSection(1, 80);
    m_rows->header()->resizeSection(2, 220);
    m_rows->header()->resizeSection(3, 110);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton *copy = buttons->addButton(tr("&Copy Report"), QDialogButtonBox::ActionRole);
    connect(copy, &QPushButton::clicked, this,
            [this] { QApplication::clipboard()->setText(m_report.summary()); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(headline);
    layout->addWidget(m_rows, 1);
    layout->addWidget(buttons);
    resize(820, 420);
}

} // namespace db::widgets
