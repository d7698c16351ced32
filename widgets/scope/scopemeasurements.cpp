#include "scopemeasurements.h"

#include "scope/analysis.h"
#include "scope/recorder.h"
#include "scopeplot.h"
#include "widgets/common/widgetstyle.h"

#include <QHeaderView>

#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace db::widgets {

QString scopeNumber(double value)
{
    if (!std::isfinite(value))
        return QStringLiteral("—");
    return QLocale::c().toString(value, 'g', 5);
}

QString scopeNumber(double value, int decimals)
{
    if (!std::isfinite(value))
        return QStringLiteral("—");
    return QLocale::c().toString(value, 'f', std::clamp(decimals, 0, 12));
}

ScopeMeasurements::ScopeMeasurements(QWidget *parent)
    : QWidget(parent)
    , m_summary(new QLabel(this))
    , m_table(new QTableWidget(0, ColumnCount, this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    m_summary->setObjectName(QStringLiteral("cursorSummary"));
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setWordWrap(true); // the plot beside the controls fits a laptop screen
    m_table->setObjectName(QStringLiteral("measurementTable"));
    m_table->setHorizontalHeaderLabels({ tr("Channel"), tr("Unit"), tr("at A"), tr("at B"),
                                         tr("B − A"), tr("Mean"), tr("RMS"), tr("Min"), tr("Max"),
                                         tr("P-P") });
    m_table->horizontalHeaderItem(Dy)->setToolTip(tr("dy: value at B minus value at A"));
    m_table->horizontalHeaderItem(PeakToPeak)->setToolTip(tr("peak-to-peak between A and B"));
    m_table->verticalHeader()->setVisible(false);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setAlternatingRowColors(true);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(Channel, QHeaderView::Stretch);
    m_table->setTextElideMode(Qt::ElideMiddle);
    m_table->setFont(style::monospaceFont());
    m_table->horizontalHeader()->setFont(font());
    clear();
}

void ScopeMeasurements::clear()
{
    m_summary->setText(tr("Cursors off: switch them on to measure between A and B."));
    m_table->setRowCount(0);
}

void ScopeMeasurements::update(const scope::Recorder &recorder, const ScopePlot &plot, double a,
                               double b)
{
    const double dt = b - a;
    const double origin = plot.timeOrigin();
    m_summary->setText(tr("<b>A</b> %1 s &nbsp; <b>B</b> %2 s &nbsp; <b>Δt</b> %3 s &nbsp; "
                          "<b>1/Δt</b> %4 Hz")
                           .arg(scopeNumber(a - origin), scopeNumber(b - origin), scopeNumber(dt),
                                scopeNumber(dt != 0.0 ? 1.0 / dt : INFINITY)));
    QList<int> rows;
    for (int i = 0; i < recorder.channelCount(); ++i) {
        if (plot.channelStyle(i).visible)
            rows.append(i);
    }
    m_table->setRowCount(int(rows.size()));
    for (int r = 0; r < rows.size(); ++r) {
        const int channel = rows[r];
        const scope::ChannelInfo &info = recorder.channelInfo(channel);
        const scope::TraceBuffer &buffer = recorder.buffer(channel);
        const double va = scope::analysis::valueAt(buffer, a, info);
        const double vb = scope::analysis::valueAt(buffer, b, info);
        const scope::analysis::Statistics s =
            scope::analysis::statistics(buffer, std::min(a, b), std::max(a, b), info);
        const bool any = s.count > 0;
        const double figures[] = { va,
                                   vb,
                                   vb - va,
                                   any ? s.mean : NAN,
                                   any ? s.rms : NAN,
                                   any ? s.min : NAN,
                                   any ? s.max : NAN,
                                   any ? s.peakToPeak : NAN };
        auto *name = new QTableWidgetItem(scopeChannelName(recorder, channel));
        name->setForeground(plot.channelStyle(channel).color.darker(115));
        name->setFont(font());
        name->setToolTip(info.deviceLabel());
        m_table->setItem(r, Channel, name);
        auto *unit = new QTableWidgetItem(info.unit);
        unit->setFont(font());
        m_table->setItem(r, Unit, unit);
        double magnitude = 0;
        for (const double v : figures) {
            if (std::isfinite(v))
                magnitude = std::max(magnitude, std::abs(v));
        }
        const int decimals = info.displayDecimals(magnitude);
        for (int c = AtA; c < ColumnCount; ++c) {
            const bool average = c == Mean || c == Rms;
            auto *item =
                new QTableWidgetItem(scopeNumber(figures[c - AtA], decimals + (average ? 1 : 0)));
            item->setData(Qt::UserRole, figures[c - AtA]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(r, c, item);
        }
    }
}

double ScopeMeasurements::value(int row, Column column) const
{
    const QTableWidgetItem *item = m_table->item(row, column);
    if (!item)
        return NAN;
    bool ok = false;
    const double v = item->data(Qt::UserRole).toDouble(&ok);
    return ok ? v : NAN;
}

} // namespace db::widgets
