// ScopePage: channels, recording, drag and drop, cursors, files and analysis.
#include "scopepage.h"

#include "core/deviceconnection.h"
#include "core/filewriter.h"
#include "scope/csv.h"
#include "scope/pollingsource.h"
#include "scope/recorder.h"
#include "scopeanalysisdialog.h"
#include "scopechannelmodel.h"
#include "scopecursors.h"
#include "scopemeasurements.h"
#include "scopeplot.h"
#include "widgets/common/plot.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QMimeData>
#include <QSpinBox>
#include <QTableView>

namespace db::widgets {

void ScopePage::setConnection(DeviceConnection *connection)
{
    if (connection == m_connection)
        return;
    m_devices.removeAll(nullptr);
    if (connection && !m_devices.contains(connection))
        m_devices.append(connection);
    if (!connection)
        m_recorder->stop(); // no device left (or the window closes)
    // The old connection's sources: a running recording keeps them until it ends; otherwise
    // their channels stay in the recorder (orphans) and are made again at the next Start.
    if (m_recorder->isRunning()) {
        m_otherSources.append(m_source.data());
        m_otherSources.append(m_pdoSource.data());
        m_source = nullptr;
        m_pdoSource = nullptr;
    } else {
        delete m_source;
        delete m_pdoSource;
    }
    delete m_pdoRequest; // a lookup on the old connection
    m_unmapped.clear();
    m_connection = connection;
    m_addressEdit->setPlaceholderText(tr("Object address, e.g. %1").arg(addressFormat().example()));
    m_addressEdit->setToolTip(tr("Object addresses (%1 and %2, as the device writes them), "
                                 "separated by commas")
                                  .arg(addressFormat().indexName(), addressFormat().subName()));
    updateControls();
}

const AddressFormat &ScopePage::addressFormat() const
{
    return m_connection ? m_connection->addressFormat() : AddressFormat::canopen();
}

Result<QList<ObjectAddress>> ScopePage::parseObjects(const QMimeData *mime,
                                                     const AddressFormat &format)
{
    if (!mime || !mime->hasFormat(QString::fromLatin1(kObjectsMimeType)))
        return Error(Error::Kind::InvalidArgument, tr("no drivebench objects in the drop"));
    const QString text = QString::fromUtf8(mime->data(QString::fromLatin1(kObjectsMimeType)));
    QStringList lines = text.split(QLatin1Char('\n'));
    // "addresses KEY" first when the objects are not CANopen ones (OdEditorModel::mimeData).
    QString dropped = AddressFormat::canopen().key();
    int lineNumber = 0;
    if (!lines.isEmpty() && lines.first().trimmed().startsWith(QLatin1String("addresses "))) {
        dropped = lines.takeFirst().trimmed().mid(10).trimmed();
        ++lineNumber;
    }
    if (dropped != format.key())
        return Error(Error::Kind::InvalidArgument,
                     tr("the dropped objects have %1 addresses, this device's are %2 addresses "
                        "(like %3)")
                         .arg(dropped, format.key(), format.example()));
    QList<ObjectAddress> addresses;
    for (const QString &raw : std::as_const(lines)) {
        ++lineNumber;
        const QString line = raw.trimmed();
        if (line.isEmpty())
            continue;
        const Result<ObjectAddress> a = format.parse(line);
        if (!a)
            return Error(Error::Kind::InvalidArgument,
                         tr("line %1 \"%2\": %3").arg(lineNumber).arg(line, a.error().message()));
        addresses.append(*a);
    }
    if (addresses.isEmpty())
        return Error(Error::Kind::InvalidArgument, tr("the drop holds no object address"));
    return addresses;
}

Result<void> ScopePage::addChannels(const QList<ObjectAddress> &addresses, int rateMs)
{
    if (m_recorder->isRunning())
        return Error(Error::Kind::Busy, tr("stop recording to change the channels"));
    if (!m_connection)
        return Error(Error::Kind::InvalidArgument,
                     tr("no device: connect one to add channels from it"));
    if (!m_source)
        m_source = new scope::PollingSource(m_connection, this);
    const int rate = rateMs >= 0 ? rateMs : m_rateBox->value();
    const QString device = m_connection->uri().toString();
    QStringList problems;
    for (const ObjectAddress &address : addresses) {
        bool present = false;
        for (int i = 0; i < m_recorder->channelCount(); ++i) {
            const scope::ChannelInfo &info = m_recorder->channelInfo(i);
            present = present || (info.address == address && info.device == device);
        }
        if (present) {
            problems.append(tr("%1 is already recorded").arg(addressFormat().format(address)));
            continue;
        }
        const scope::ChannelInfo info = channelFor(address, rate);
        const Result<int> index = m_source->addChannel(info);
        if (!index) {
            problems.append(
                tr("%1: %2").arg(addressFormat().format(address), index.error().message()));
            continue;
        }
        m_model->setRateMs(ScopeChannelModel::key(info), rate);
        m_recorder->addChannel(m_source, *index);
    }
    if (!problems.isEmpty()) {
        const QString text = problems.join(QStringLiteral("; "));
        showMessage(text, true);
        return Error(Error::Kind::InvalidArgument, text);
    }
    showMessage(
        tr("%n channel(s) ready; press Start to record.", nullptr, m_recorder->channelCount()),
        false);
    return {};
}

scope::ChannelInfo ScopePage::channelFor(ObjectAddress address, int rateMs) const
{
    scope::ChannelInfo info =
        scope::ChannelInfo::forObject(address, m_connection->dictionary(),
                                      m_connection->uri().toString(), rateMs, &addressFormat());
    info.deviceName = deviceName(m_connection);
    return info;
}

QString ScopePage::deviceName(const DeviceConnection *connection) const
{
    if (!connection)
        return {};
    const auto base = [](const DeviceConnection *c) {
        // "ACTIVE Cube ACU (VABus/TCP)": the part in brackets names the link, not the device.
        const QString product = c->dictionary().identity.productName;
        QString name = product.left(product.indexOf(QLatin1String(" ("))).trimmed();
        if (name.isEmpty())
            name = c->protocolKey();
        return c->uri().host().isEmpty() ? name : name + QLatin1Char(' ') + c->uri().host();
    };
    QString name = base(connection);
    bool clash = false;
    for (const QPointer<DeviceConnection> &other : m_devices)
        clash = clash || (other && other != connection && base(other) == name);
    if (clash && connection->uri().port() >= 0)
        name += QLatin1Char(':') + QString::number(connection->uri().port());
    if (clash && connection->networkAddress() > 0)
        name += tr(" node %1").arg(connection->networkAddress());
    return name;
}

DeviceConnection *ScopePage::connectionOf(const QString &device) const
{
    for (const QPointer<DeviceConnection> &c : m_devices) {
        if (c && c->uri().toString() == device)
            return c;
    }
    return nullptr;
}

QString ScopePage::pdoKey(const QString &device, const QString &id)
{
    return device + QLatin1Char('\n') + id;
}

bool ScopePage::removeChannel(int index)
{
    if (!m_recorder->isRunning() && index >= 0 && index < m_recorder->channelCount())
        m_pdoMappings.remove(
            pdoKey(m_recorder->channelInfo(index).device, m_recorder->channelInfo(index).id));
    // The source keeps polling the object until Start re-creates it; the recorder forgets it now.
    return m_recorder->removeChannel(index);
}

void ScopePage::addFromEdit()
{
    QList<ObjectAddress> addresses;
    for (const QString &part : m_addressEdit->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const Result<ObjectAddress> a = addressFormat().parse(part.trimmed());
        if (!a) {
            showMessage(tr("\"%1\": %2").arg(part.trimmed(), a.error().message()), true);
            return;
        }
        addresses.append(*a);
    }
    if (addresses.isEmpty()) {
        showMessage(tr("Type an object address such as %1.").arg(addressFormat().example()), true);
        return;
    }
    if (channelSource() == ChannelSource::Pdo) {
        addPdoChannels(addresses);
        m_addressEdit->clear();
    } else if (addChannels(addresses)) {
        m_addressEdit->clear();
    }
}

void ScopePage::removeSelected()
{
    const QModelIndex current = m_channelView->currentIndex();
    if (current.isValid())
        removeChannel(current.row());
}

void ScopePage::chooseColor(int row)
{
    ScopeChannelStyle style = m_plot->channelStyle(row);
    const QColor color = QColorDialog::getColor(style.color, this, tr("Channel colour"));
    if (!color.isValid())
        return;
    style.color = color;
    m_plot->setChannelStyle(row, style);
}

void ScopePage::dragEnterEvent(QDragEnterEvent *event)
{
    if (event->mimeData()->hasFormat(QString::fromLatin1(kObjectsMimeType))
        && !m_recorder->isRunning())
        event->acceptProposedAction();
}

void ScopePage::dropEvent(QDropEvent *event)
{
    const Result<QList<ObjectAddress>> addresses = parseObjects(event->mimeData(), addressFormat());
    if (!addresses) {
        showMessage(addresses.error().message(), true);
        return;
    }
    if (channelSource() == ChannelSource::Pdo)
        addPdoChannels(*addresses);
    else
        addChannels(*addresses);
    event->acceptProposedAction();
}

scope::Trigger ScopePage::triggerSettings() const
{
    scope::Trigger t;
    t.channel = m_triggerChannelBox->count() > 0 ? m_triggerChannelBox->currentIndex() : -1;
    t.kind = scope::Trigger::Kind(m_triggerKindBox->currentIndex());
    t.level = m_levelBox->value();
    t.level2 = m_level2Box->value();
    t.bit = m_bitBox->value();
    t.preTriggerS = m_preBox->value();
    t.postTriggerS = m_postBox->value();
    return t;
}

void ScopePage::setTriggerSettings(const scope::Trigger &trigger)
{
    if (trigger.channel >= 0 && trigger.channel < m_triggerChannelBox->count())
        m_triggerChannelBox->setCurrentIndex(trigger.channel);
    m_triggerKindBox->setCurrentIndex(int(trigger.kind));
    m_levelBox->setValue(trigger.level);
    m_level2Box->setValue(trigger.level2);
    m_bitBox->setValue(trigger.bit);
    m_preBox->setValue(trigger.preTriggerS);
    m_postBox->setValue(trigger.postTriggerS);
}

void ScopePage::setMode(int mode)
{
    m_modeBox->setCurrentIndex(mode);
}

void ScopePage::start()
{
    if (m_recorder->isRunning())
        return;
    if (!m_connection || !m_connection->isConnected()) {
        showMessage(tr("No connected device: connect one first."), true);
        return;
    }
    if (m_recorder->channelCount() == 0) {
        showMessage(tr("No channels: add an object address or drag objects here."), true);
        return;
    }
    const scope::Trigger trigger = triggerSettings();
    if (const Result<void> r = rebuildSource(); !r) {
        showMessage(r.error().message(), true);
        return;
    }
    setTriggerSettings(trigger);
    if (trigger.channel >= 0 && trigger.channel < m_recorder->channelCount())
        m_triggerChoice = ScopeChannelModel::key(m_recorder->channelInfo(trigger.channel));
    const auto mode = scope::Recorder::Mode(m_modeBox->currentIndex());
    m_recorder->setMode(mode);
    m_recorder->setRollWindowS(m_rollBox->value());
    m_recorder->setTrigger(trigger);
    showMessage({}, false);
    m_recorder->start();
    watchPdoArrival();
}

void ScopePage::stop()
{
    m_recorder->stop();
}

void ScopePage::setCursorsEnabled(bool enabled)
{
    if (m_cursorAction->isChecked() != enabled)
        m_cursorAction->setChecked(enabled); // comes back here through toggled()
    ScopeCursors *cursors = m_plot->cursors();
    if (enabled && !cursors->isEnabled())
        cursors->placeWithin(m_plot->timeLower(), m_plot->timeUpper());
    cursors->setEnabled(enabled);
    m_plot->customPlot()->replot(QCustomPlot::rpQueuedReplot);
    scheduleMeasurements();
}

bool ScopePage::cursorsEnabled() const
{
    return m_plot->cursors()->isEnabled();
}

void ScopePage::scheduleMeasurements()
{
    if (!m_measureTimer.isActive())
        m_measureTimer.start();
}

void ScopePage::measure()
{
    ScopeCursors *cursors = m_plot->cursors();
    if (!cursors->isEnabled()) {
        m_measurements->clear();
        return;
    }
    m_measurements->update(*m_recorder, *m_plot, cursors->a(), cursors->b());
}

Result<void> ScopePage::openRecording(const QString &fileName)
{
    Result<scope::Recording> recording = scope::csv::load(fileName);
    if (!recording)
        return recording.error();
    const scope::Trigger trigger = recording->trigger;
    QList<scope::ChannelInfo> infos;
    for (const scope::RecordedChannel &c : recording->channels)
        infos.append(c.info);
    m_recorder->load(std::move(*recording)); // the samples move, a large file is not copied
    for (const scope::ChannelInfo &info : infos)
        m_model->setRateMs(ScopeChannelModel::key(info), info.sourceRateMs);
    if (trigger.isValid())
        setTriggerSettings(trigger);
    m_plot->autoscale();
    return {};
}

void ScopePage::promptOpen()
{
    const QString file = QFileDialog::getOpenFileName(this, tr("Open recording"), {},
                                                      tr("Recordings (*.csv);;All files (*)"));
    if (file.isEmpty())
        return;
    const Result<void> r = openRecording(file);
    showMessage(r ? tr("Opened %1").arg(QFileInfo(file).fileName()) : r.error().message(), !r);
}

void ScopePage::showAnalysis()
{
    int channel =
        m_channelView->currentIndex().isValid() ? m_channelView->currentIndex().row() : -1;
    for (int i = 0; channel < 0 && i < m_recorder->channelCount(); ++i) {
        if (m_plot->channelStyle(i).visible)
            channel = i;
    }
    if (channel < 0) {
        showMessage(tr("Nothing to analyse: record or open a recording first."), true);
        return;
    }
    ScopeCursors *cursors = m_plot->cursors();
    const double t0 =
        cursors->isEnabled() ? std::min(cursors->a(), cursors->b()) : m_plot->timeLower();
    const double t1 =
        cursors->isEnabled() ? std::max(cursors->a(), cursors->b()) : m_plot->timeUpper();
    auto *dialog = new ScopeAnalysisDialog(m_recorder->channelInfo(channel),
                                           m_recorder->buffer(channel), t0, t1, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
}

} // namespace db::widgets
