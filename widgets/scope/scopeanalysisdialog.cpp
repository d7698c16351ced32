#include "scopeanalysisdialog.h"

#include "scopemeasurements.h"
#include "widgets/common/plot.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>

namespace db::widgets {

namespace {

// The samples of buffer with t0 <= t <= t1, gaps kept.
scope::TraceBuffer slice(const scope::TraceBuffer &buffer, double t0, double t1)
{
    const qint64 lo = buffer.lowerBound(t0);
    const qint64 hi = buffer.upperBound(t1);
    scope::TraceBuffer out(std::max<qint64>(1, hi - lo));
    for (qint64 i = lo; i < hi; ++i) {
        if (i > lo && buffer.startsGap(i))
            out.markGap();
        out.append(buffer.time(i), buffer.value(i));
    }
    return out;
}

QLabel *figure(const QString &text)
{
    auto *label = new QLabel(text);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

} // namespace

ScopeAnalysisDialog::ScopeAnalysisDialog(const scope::ChannelInfo &info,
                                         const scope::TraceBuffer &buffer, double t0, double t1,
                                         QWidget *parent)
    : QDialog(parent)
    , m_samples(slice(buffer, t0, t1))
    , m_spectrum(scope::analysis::spectrum(m_samples, t0, t1, info))
    , m_step(scope::analysis::stepResponse(m_samples, t0, t1, info))
    , m_statistics(scope::analysis::statistics(m_samples, t0, t1, info))
    , m_plot(new QCustomPlot(this))
{
    setWindowTitle(tr("Analysis: %1").arg(info.displayLabel()));
    setObjectName(QStringLiteral("scopeAnalysis"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("<b>%1</b> from %2 s to %3 s (%4 samples)")
                                     .arg(info.displayLabel().toHtmlEscaped(), scopeNumber(t0),
                                          scopeNumber(t1), QString::number(m_statistics.count))));
    auto *row = new QHBoxLayout;
    m_plot->setMinimumSize(460, 300);
    row->addWidget(m_plot, 1);
    auto *figures = new QGroupBox(tr("Figures"), this);
    auto *form = new QFormLayout(figures);
    row->addWidget(figures);
    layout->addLayout(row, 1);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    fillSpectrum(info);
    fillFigures(form, info);
    resize(820, 420);
}

void ScopeAnalysisDialog::fillSpectrum(const scope::ChannelInfo &info)
{
    m_plot->xAxis->setLabel(tr("frequency (Hz)"));
    m_plot->yAxis->setLabel(info.unit.isEmpty() ? tr("amplitude")
                                                : tr("amplitude [%1]").arg(info.unit));
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    if (!m_spectrum) {
        auto *text = new QCPItemText(m_plot);
        text->position->setType(QCPItemPosition::ptAxisRectRatio);
        text->position->setCoords(0.5, 0.5);
        text->setText(tr("No spectrum: %1").arg(m_spectrum.error().message()));
        m_plot->replot();
        return;
    }
    // Log-log: drive spectra span decades in both; DC (removed mean) and zeros are left out.
    QVector<double> f;
    QVector<double> a;
    for (qsizetype k = 1; k < m_spectrum->frequency.size(); ++k) {
        if (m_spectrum->amplitude[k] > 0.0) {
            f.append(m_spectrum->frequency[k]);
            a.append(m_spectrum->amplitude[k]);
        }
    }
    QCPGraph *g = m_plot->addGraph();
    g->setPen(QPen(QColor(31, 119, 180), 1.2));
    g->setData(f, a, true);
    for (QCPAxis *axis : { m_plot->xAxis, m_plot->yAxis }) {
        axis->setScaleType(QCPAxis::stLogarithmic);
        axis->setTicker(QSharedPointer<QCPAxisTickerLog>::create());
        axis->setNumberFormat(QStringLiteral("gb"));
        axis->grid()->setSubGridVisible(true);
    }
    g->rescaleAxes();
    m_plot->replot();
}

void ScopeAnalysisDialog::fillFigures(QFormLayout *form, const scope::ChannelInfo &info)
{
    const QString unit = info.unit.isEmpty() ? QString() : QLatin1Char(' ') + info.unit;
    const auto value = [&unit](double v) {
        return scopeNumber(v) + unit;
    };
    const auto seconds = [](double v) {
        return scopeNumber(v) + QStringLiteral(" s");
    };
    const scope::analysis::Statistics &s = m_statistics;
    form->addRow(tr("Mean"), figure(value(s.mean)));
    form->addRow(tr("RMS"), figure(value(s.rms)));
    form->addRow(tr("Std. deviation"), figure(value(s.stdDev)));
    form->addRow(tr("Min / max"), figure(value(s.min) + QStringLiteral(" / ") + value(s.max)));
    form->addRow(tr("Peak-peak"), figure(value(s.peakToPeak)));
    if (m_spectrum) {
        form->addRow(tr("Spectral peak"),
                     figure(scopeNumber(m_spectrum->peakFrequency()) + QStringLiteral(" Hz")));
        form->addRow(tr("Sample period"), figure(seconds(m_spectrum->samplePeriodS)));
    }
    if (!m_step) {
        form->addRow(tr("Step response"), figure(m_step.error().message()));
        return;
    }
    const scope::analysis::StepResponse &r = *m_step;
    form->addRow(tr("Step"), figure(value(r.initial) + QStringLiteral(" → ") + value(r.final)));
    form->addRow(tr("Rise time (10–90 %)"), figure(seconds(r.riseTime)));
    form->addRow(tr("Overshoot"), figure(scopeNumber(r.overshootPercent) + QStringLiteral(" %")));
    form->addRow(
        tr("Peak"),
        figure(value(r.peakValue) + tr(", %1 after the step start").arg(seconds(r.peakTime))));
    form->addRow(tr("Settling time (2 %)"), figure(seconds(r.settlingTime)));
}

} // namespace db::widgets
