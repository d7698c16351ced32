#pragma once

#include <QWidget>

#include <cmath>

class QLabel;
class QTableWidget;

namespace db::scope {
class Recorder;
}

namespace db::widgets {

class ScopePlot;

// The cursor measurement table: the A/B times (from the plot's time origin) with dt and 1/dt,
// and per visible channel its unit, value at A and B, dy = B - A, and mean, RMS, min, max and
// peak-to-peak of the samples between the cursors (scope/analysis.h, displayed units). A
// channel's figures have the same decimals (its object's, or for floating-point values enough
// for five digits of its largest figure); mean and RMS one more.
class ScopeMeasurements : public QWidget
{
    Q_OBJECT
public:
    enum Column { Channel, Unit, AtA, AtB, Dy, Mean, Rms, Min, Max, PeakToPeak, ColumnCount };

    explicit ScopeMeasurements(QWidget *parent = nullptr);

    // Recomputes everything for cursors a and b (seconds). Cost: O(samples between cursors).
    void update(const scope::Recorder &recorder, const ScopePlot &plot, double a, double b);
    // Shows that the cursors are off.
    void clear();

    QTableWidget *table() const { return m_table; }
    QLabel *summary() const { return m_summary; }
    // The number shown in a cell, NaN when the cell is empty or not a number (tests).
    double value(int row, Column column) const;

private:
    QLabel *m_summary;
    QTableWidget *m_table;
};

// A measured figure as text: 5 significant digits, "—" for NaN/inf.
QString scopeNumber(double value);
// A figure with exactly `decimals` decimal places in the C locale, "—" for NaN/inf.
QString scopeNumber(double value, int decimals);

} // namespace db::widgets
