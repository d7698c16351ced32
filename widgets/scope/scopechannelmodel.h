#pragma once

#include "scope/recorder.h"
#include <QAbstractTableModel>
#include <QHash>
#include <QPointer>

namespace db::widgets {

class ScopePlot;

// The scope's channels as a table: visibility (check box) and colour, display scaling, lane
// (value axis) and polling rate; unit, device and sample counts in the tooltip. A view of the
// Recorder (what a channel is, its scaling) and the ScopePlot (how it is drawn); edits go straight
// to them. The polling rate is kept here per channel id and applied by the scope page when it
// (re)creates its sources.
class ScopeChannelModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { Name, Scale, Offset, Lane, Rate, ColumnCount };

    ScopeChannelModel(scope::Recorder *recorder, ScopePlot *plot, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // Polling period in ms of a channel (its id), default `fallback`.
    // Polling periods by key(): the same object of two devices has its own.
    static QString key(const scope::ChannelInfo &info);
    int rateMs(const QString &key, int fallback = 0) const { return m_rates.value(key, fallback); }
    void setRateMs(const QString &key, int rateMs);
    // Re-reads the sample counters (called by the page a few times per second).
    void refreshCounts();

private:
    void reset();

    QPointer<scope::Recorder> m_recorder;
    ScopePlot *m_plot;
    QHash<QString, int> m_rates;
    int m_rows = 0;
};

} // namespace db::widgets
