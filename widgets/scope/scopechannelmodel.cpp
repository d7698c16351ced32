#include "scopechannelmodel.h"

#include "scope/recorder.h"
#include "scopeplot.h"

#include <QLocale>
#include <QPainter>
#include <QPixmap>

#include <cmath>

namespace db::widgets {

namespace {
QPixmap swatch(const QColor &color)
{
    QPixmap pixmap(14, 14);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(color.darker(130));
    p.setBrush(color);
    p.drawRoundedRect(QRectF(1.5, 1.5, 11, 11), 2, 2);
    return pixmap;
}
} // namespace

ScopeChannelModel::ScopeChannelModel(scope::Recorder *recorder, ScopePlot *plot, QObject *parent)
    : QAbstractTableModel(parent)
    , m_recorder(recorder)
    , m_plot(plot)
{
    connect(recorder, &scope::Recorder::channelsChanged, this, &ScopeChannelModel::reset);
    connect(plot, &ScopePlot::channelStyleChanged, this,
            [this](int row) { Q_EMIT dataChanged(index(row, 0), index(row, ColumnCount - 1)); });
    m_rows = recorder->channelCount();
}

void ScopeChannelModel::reset()
{
    beginResetModel();
    m_rows = m_recorder ? m_recorder->channelCount() : 0;
    endResetModel();
}

void ScopeChannelModel::refreshCounts()
{
    if (m_rows > 0)
        Q_EMIT dataChanged(index(0, Name), index(m_rows - 1, Name), { Qt::ToolTipRole });
}

QString ScopeChannelModel::key(const scope::ChannelInfo &info)
{
    return info.device + QLatin1Char('\n') + info.id;
}

void ScopeChannelModel::setRateMs(const QString &key, int rateMs)
{
    m_rates.insert(key, std::max(0, rateMs));
}

int ScopeChannelModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_rows;
}

int ScopeChannelModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ScopeChannelModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Name:
        return tr("Channel");
    case Scale:
        return tr("Scale");
    case Offset:
        return tr("Offset");
    case Lane:
        return tr("Axis");
    case Rate:
        return tr("Rate (ms)");
    default:
        return {};
    }
}

Qt::ItemFlags ScopeChannelModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == Name)
        f |= Qt::ItemIsUserCheckable;
    if (index.column() == Scale || index.column() == Offset || index.column() == Lane
        || (index.column() == Rate && m_recorder && !m_recorder->isRunning()))
        f |= Qt::ItemIsEditable;
    return f;
}

QVariant ScopeChannelModel::data(const QModelIndex &index, int role) const
{
    if (!m_recorder || !index.isValid() || index.row() >= m_recorder->channelCount())
        return {};
    const int row = index.row();
    const scope::ChannelInfo &info = m_recorder->channelInfo(row);
    const ScopeChannelStyle style = m_plot->channelStyle(row);
    const bool edit = role == Qt::EditRole;
    if (role == Qt::CheckStateRole && index.column() == Name)
        return style.visible ? Qt::Checked : Qt::Unchecked;
    if (role == Qt::DecorationRole && index.column() == Name)
        return swatch(style.color);
    if (role == Qt::ToolTipRole) {
        const scope::TraceBuffer &b = m_recorder->buffer(row);
        return tr("%1 [%2]\ndevice: %3\ndisplay = raw × %4 + %5\n%6 samples, %7 lost\n"
                  "double-click the name to change the colour")
            .arg(info.displayLabel(), info.unit,
                 info.deviceName.isEmpty()
                     ? info.device
                     : QStringLiteral("%1 (%2)").arg(info.deviceName, info.device),
                 QString::number(info.scale), QString::number(info.offset),
                 QLocale().toString(b.size()), QLocale().toString(b.dropped()));
    }
    if (role == Qt::TextAlignmentRole && index.column() >= Scale)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && !edit)
        return {};
    switch (index.column()) {
    case Name:
        return scopeChannelName(*m_recorder, row);
    case Scale:
        return edit ? QVariant(info.scale) : QVariant(QString::number(info.scale, 'g', 8));
    case Offset:
        return edit ? QVariant(info.offset) : QVariant(QString::number(info.offset, 'g', 8));
    case Lane:
        return style.lane;
    case Rate: {
        const int rate = rateMs(key(info), info.sourceRateMs);
        return edit || rate > 0 ? QVariant(rate) : QVariant(tr("max"));
    }
    default:
        return {};
    }
}

bool ScopeChannelModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!m_recorder || !index.isValid() || index.row() >= m_recorder->channelCount())
        return false;
    const int row = index.row();
    const scope::ChannelInfo info = m_recorder->channelInfo(row);
    ScopeChannelStyle style = m_plot->channelStyle(row);
    if (role == Qt::CheckStateRole && index.column() == Name) {
        style.visible = value.toInt() == Qt::Checked;
        m_plot->setChannelStyle(row, style);
        return true;
    }
    if (role != Qt::EditRole)
        return false;
    bool ok = false;
    switch (index.column()) {
    case Scale: {
        const double scale = value.toDouble(&ok);
        if (!ok || scale == 0.0 || !std::isfinite(scale))
            return false; // display = raw * scale must stay invertible
        m_recorder->setScaling(row, scale, info.offset);
        return true;
    }
    case Offset: {
        const double offset = value.toDouble(&ok);
        if (!ok || !std::isfinite(offset))
            return false;
        m_recorder->setScaling(row, info.scale, offset);
        return true;
    }
    case Lane: {
        const int lane = value.toInt(&ok);
        if (!ok || lane < 1 || lane > ScopePlot::kMaxLanes)
            return false;
        style.lane = lane;
        m_plot->setChannelStyle(row, style);
        return true;
    }
    case Rate: {
        const int rate = value.toInt(&ok);
        if (!ok || rate < 0)
            return false;
        setRateMs(key(info), rate);
        Q_EMIT dataChanged(index, index);
        return true;
    }
    default:
        return false;
    }
}

} // namespace db::widgets
