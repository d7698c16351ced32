#pragma once

#include "core/result.h"
#include "scope/analysis.h"

#include <QDialog>

class QCustomPlot;
class QFormLayout;
class QLabel;

namespace db::widgets {

// Spectrum, step response and statistics of one channel over [t0, t1] (scope/analysis.h), in a
// small non-modal dialog. The samples of the range are copied, so the dialog stays valid while
// the recorder goes on.
class ScopeAnalysisDialog : public QDialog
{
    Q_OBJECT
public:
    ScopeAnalysisDialog(const scope::ChannelInfo &info, const scope::TraceBuffer &buffer, double t0,
                        double t1, QWidget *parent = nullptr);

    const Result<scope::analysis::Spectrum> &spectrum() const { return m_spectrum; }
    const Result<scope::analysis::StepResponse> &stepResponse() const { return m_step; }
    const scope::analysis::Statistics &statistics() const { return m_statistics; }
    QCustomPlot *spectrumPlot() const { return m_plot; }

private:
    void fillSpectrum(const scope::ChannelInfo &info);
    void fillFigures(QFormLayout *form, const scope::ChannelInfo &info);

    scope::TraceBuffer m_samples;
    Result<scope::analysis::Spectrum> m_spectrum;
    Result<scope::analysis::StepResponse> m_step;
    scope::analysis::Statistics m_statistics;
    QCustomPlot *m_plot;
};

} // namespace db::widgets
