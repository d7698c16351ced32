// ScopePage: channel sources (host polling, passive CANopen PDOs) and the opt-in TPDO mapping.
#include "scopepage.h"

#include "canopen/cannetwork.h"
#include "canopen/nodemonitor.h"
#include "canopen/pdoclient.h"
#include "scope/pdodiscovery.h"
#include "scope/recorder.h"
#include "scopechannelmodel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QIdentityProxyModel>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSet>
#include <QSpinBox>
#include <QTimer>

#include <functional>

namespace db::widgets {

namespace {

constexpr int kDefaultEventMs = 10; // "Map to TPDO…" when the rate box says "max rate"

// The channel table: the page's ScopeChannelModel, with the PDO of PDO channels in the rate
// column (not editable there: the device decides when a PDO is sent).
class ChannelTableModel : public QIdentityProxyModel
{
public:
    ChannelTableModel(ScopeChannelModel *model, std::function<QString(int, bool)> note,
                      QObject *parent)
        : QIdentityProxyModel(parent)
        , m_note(std::move(note))
    {
        setSourceModel(model);
    }

    QVariant data(const QModelIndex &index, int role) const override
    {
        if (index.column() == ScopeChannelModel::Rate
            && (role == Qt::DisplayRole || role == Qt::ToolTipRole)) {
            const QString note = m_note(index.row(), role == Qt::ToolTipRole);
            if (!note.isEmpty())
                return note;
        }
        return QIdentityProxyModel::data(index, role);
    }

    Qt::ItemFlags flags(const QModelIndex &index) const override
    {
        Qt::ItemFlags f = QIdentityProxyModel::flags(index);
        if (index.column() == ScopeChannelModel::Rate && !m_note(index.row(), false).isEmpty())
            f &= ~Qt::ItemIsEditable;
        return f;
    }

private:
    std::function<QString(int, bool)> m_note;
};

} // namespace

QAbstractItemModel *ScopePage::createTableModel()
{
    return new ChannelTableModel(
        m_model,
        [this](int row, bool tooltip) -> QString {
            if (row < 0 || row >= m_recorder->channelCount())
                return {};
            const scope::ChannelInfo &info = m_recorder->channelInfo(row);
            const auto found = m_pdoMappings.constFind(pdoKey(info.device, info.id));
            if (found == m_pdoMappings.cend())
                return {};
            const scope::PdoSource::Mapping *it = &found->mapping;
            const QString cob = QStringLiteral("0x%1").arg(it->cobId, 3, 16, QLatin1Char('0'));
            if (!tooltip)
                return tr("PDO %1").arg(cob);
            const int size = datatype::byteSize(it->type);
            QString text = tr("Sampled passively from the PDO with COB-ID %1, bytes %2..%3")
                               .arg(cob)
                               .arg(it->byteOffset)
                               .arg(it->byteOffset + size - 1);
            if (it->expectedPeriodMs > 0)
                text += tr(", expected every %1 ms (later frames count as lost samples)")
                            .arg(it->expectedPeriodMs);
            return text;
        },
        this);
}

QWidget *ScopePage::createSourceRow(QWidget *parent)
{
    auto *row = new QWidget(parent);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    m_sourceLabel = new QLabel(tr("Source"), row);
    m_sourceBox = new QComboBox(row);
    m_sourceBox->setObjectName(QStringLiteral("scopeSource"));
    m_sourceBox->addItems({ tr("Polling (SDO)"), tr("PDO (passive)") });
    m_sourceBox->setToolTip(
        tr("Polling: the host reads each object by SDO at the rate above.\nPDO (passive): "
           "samples the TPDOs that already carry the objects; sends nothing and changes neither "
           "the PDO configuration nor the NMT state (the node must be operational)."));
    m_mapButton = new QPushButton(tr("Map to TPDO…"), row);
    m_mapButton->setObjectName(QStringLiteral("scopeMapTpdo"));
    m_mapButton->setToolTip(tr("Map the objects that are in no TPDO into one (changes the "
                               "device's PDO configuration; asks first)"));
    layout->addWidget(m_sourceLabel);
    layout->addWidget(m_sourceBox, 1);
    layout->addWidget(m_mapButton);
    connect(m_mapButton, &QPushButton::clicked, this, &ScopePage::promptMapToTpdo);
    return row;
}

void ScopePage::setChannelSource(ChannelSource source)
{
    m_sourceBox->setCurrentIndex(int(source));
}

ScopePage::ChannelSource ScopePage::channelSource() const
{
    const bool canopen = m_connection && m_connection->protocolKey() == u"canopen";
    return canopen ? ChannelSource(m_sourceBox->currentIndex()) : ChannelSource::Polling;
}

std::optional<scope::PdoSource::Mapping> ScopePage::pdoMapping(const QString &id) const
{
    const QString device = m_connection ? m_connection->uri().toString() : QString();
    const auto it = m_pdoMappings.constFind(pdoKey(device, id));
    return it == m_pdoMappings.cend() ? std::nullopt : std::make_optional(it->mapping);
}

void ScopePage::addPdoChannels(const QList<ObjectAddress> &addresses)
{
    DeviceConnection *conn = m_connection.data();
    const canopen::NetworkNode at = canopen::networkNodeOf(conn);
    QString refused;
    if (m_recorder->isRunning())
        refused = tr("stop recording to change the channels");
    else if (!at || !conn->isConnected())
        refused = tr("PDO channels need a connected CANopen device");
    else if (m_pdoRequest)
        refused = tr("wait for the PDO configuration being read");
    if (!refused.isEmpty()) {
        showMessage(refused, true);
        Q_EMIT pdoLookupFinished(false);
        return;
    }
    showMessage(tr("Reading the PDO configuration of node %1…").arg(at.node), false);
    Reply *reply = scope::discoverPdoChannels(conn, addresses);
    m_pdoRequest = reply;
    connect(reply, &Reply::finished, this, [this, reply] { onPdoPlan(reply); });
    updateControls();
}

void ScopePage::onPdoPlan(Reply *reply)
{
    reply->deleteLater();
    m_pdoRequest = nullptr;
    DeviceConnection *conn = m_connection.data();
    const canopen::NetworkNode at = canopen::networkNodeOf(conn);
    if (!reply->ok() || !at || m_recorder->isRunning()) {
        showMessage(reply->ok() ? tr("the connection changed or recording started")
                                : reply->error().message(),
                    true);
        updateControls();
        Q_EMIT pdoLookupFinished(false);
        return;
    }
    const auto plan = reply->value().value<scope::PdoChannelPlan>();
    if (!m_pdoSource)
        m_pdoSource = new scope::PdoSource(conn, this);
    const QString device = conn->uri().toString();
    QStringList problems;
    for (const scope::PdoChannelPlanEntry &entry : plan.found) {
        const QString id = entry.address.toString();
        bool present = false;
        for (int i = 0; i < m_recorder->channelCount(); ++i) {
            const scope::ChannelInfo &info = m_recorder->channelInfo(i);
            present = present || (info.id == id && info.device == device);
        }
        if (present) {
            problems.append(tr("%1 is already recorded").arg(id));
            continue;
        }
        const auto added = m_pdoSource->addChannel(
            channelFor(entry.address, entry.mapping.expectedPeriodMs), entry.mapping);
        if (!added) {
            problems.append(added.error().message());
            continue;
        }
        m_pdoMappings.insert(pdoKey(device, id), entry);
        m_recorder->addChannel(m_pdoSource, *added);
    }
    m_unmapped = plan.missing;
    m_tpdos.insert(device, plan.tpdos);
    // Offer the first disabled TPDO for mapping, else the last one the node has.
    m_proposedTpdo = plan.tpdos.isEmpty() ? 0 : plan.tpdos.constLast().number;
    for (const canopen::PdoConfig &c : plan.tpdos) {
        if (!c.isEnabled() || c.entries.isEmpty()) {
            m_proposedTpdo = c.number;
            break;
        }
    }
    if (!plan.missing.isEmpty())
        problems.append(plan.missingText(conn->dictionary())
                        + tr(" (use \"Map to TPDO…\" to map it)"));
    if (problems.isEmpty())
        showMessage(tr("%n PDO channel(s) added; press Start to record (node %1 must be "
                       "operational).",
                       nullptr, int(plan.found.size()))
                        .arg(at.node),
                    false);
    else
        showMessage(problems.join(QStringLiteral("; ")), true);
    updateControls();
    Q_EMIT pdoLookupFinished(problems.isEmpty());
}

void ScopePage::promptMapToTpdo()
{
    const canopen::NetworkNode at = canopen::networkNodeOf(m_connection.data());
    if (!at || m_unmapped.isEmpty())
        return;
    bool ok = false;
    const int number =
        QInputDialog::getInt(this, tr("Map to TPDO"), tr("TPDO number of node %1:").arg(at.node),
                             m_proposedTpdo + 1, 1, 4, 1, &ok);
    if (!ok)
        return;
    const int eventMs = m_rateBox->value() > 0 ? m_rateBox->value() : kDefaultEventMs;
    QStringList names;
    for (ObjectAddress a : std::as_const(m_unmapped))
        names.append(a.toString());
    const auto answer = QMessageBox::warning(
        this, tr("Change the PDO configuration?"),
        tr("This changes the PDO configuration of node %1: TPDO%2 will carry %3, sent every %4 "
           "ms. Whatever TPDO%2 carried before is replaced (in the device's RAM; nothing is "
           "stored). A PLC or other master using TPDO%2 will see the change.\n\nChange it?")
            .arg(at.node)
            .arg(number)
            .arg(names.join(QStringLiteral(", ")))
            .arg(eventMs),
        QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer == QMessageBox::Yes)
        mapToTpdo(number - 1, eventMs);
}

void ScopePage::mapToTpdo(int tpdoNumber, int eventMs)
{
    const canopen::NetworkNode at = canopen::networkNodeOf(m_connection.data());
    if (!at || m_unmapped.isEmpty() || m_pdoRequest || m_recorder->isRunning()) {
        showMessage(tr("nothing to map (add PDO channels first; stop recording)"), true);
        Q_EMIT pdoLookupFinished(false);
        return;
    }
    const QList<ObjectAddress> objects = m_unmapped;
    auto *client = new canopen::PdoClient(at.network->sdo(), this);
    Reply *reply = scope::configureTpdo(client, at.node, tpdoNumber, objects,
                                        m_connection->dictionary(), eventMs);
    client->setParent(reply);
    m_pdoRequest = reply;
    showMessage(tr("Writing TPDO%1 of node %2…").arg(tpdoNumber + 1).arg(at.node), false);
    connect(reply, &Reply::finished, this, [this, reply, objects, tpdoNumber] {
        reply->deleteLater();
        m_pdoRequest = nullptr;
        if (!reply->ok()) {
            showMessage(reply->error()
                            .prefixed(tr("TPDO%1 was not changed completely (it may be left "
                                         "disabled)")
                                          .arg(tpdoNumber + 1))
                            .message(),
                        true);
            updateControls();
            Q_EMIT pdoLookupFinished(false);
            return;
        }
        addPdoChannels(objects); // read back what the device now sends
    });
    updateControls();
}

void ScopePage::watchPdoArrival()
{
    const int run = ++m_pdoWatch;
    if (m_pdoMappings.isEmpty() || !m_recorder->isRunning())
        return;
    // PDO channels without a frame after this time get the probable cause shown, per node: the
    // channels of a recording may come from several nodes, the page's device being only one.
    const int firstPdoMs = scope::firstPdoTimeoutMs(m_pdoMappings.values());
    QTimer::singleShot(firstPdoMs, this, [this, run, firstPdoMs] {
        if (run != m_pdoWatch || !m_recorder->isRunning())
            return;
        QStringList devices; // in channel order
        QHash<QString, scope::PdoChannelPlan> silent;
        QHash<QString, QStringList> ids;
        for (int i = 0; i < m_recorder->channelCount(); ++i) {
            const scope::ChannelInfo &info = m_recorder->channelInfo(i);
            const auto it = m_pdoMappings.constFind(pdoKey(info.device, info.id));
            if (it == m_pdoMappings.cend() || m_recorder->buffer(i).size() != 0
                || m_recorder->buffer(i).lostAtSource() != 0)
                continue;
            if (!devices.contains(info.device))
                devices.append(info.device);
            silent[info.device].found.append(*it);
            ids[info.device].append(info.id);
        }
        QStringList causes;
        for (const QString &device : std::as_const(devices)) {
            const canopen::NetworkNode at = canopen::networkNodeOf(connectionOf(device));
            if (!at)
                continue;
            scope::PdoChannelPlan &plan = silent[device];
            plan.node = at.node;
            plan.tpdos = m_tpdos.value(device);
            causes.append(
                tr("No PDO within %1 s for %2: %3 (the scope never changes the NMT "
                   "state).")
                    .arg(firstPdoMs / 1000.0)
                    .arg(ids.value(device).join(QStringLiteral(", ")),
                         scope::silentPdoCause(plan, at.network->monitor()->state(at.node))));
        }
        if (!causes.isEmpty())
            showMessage(causes.join(QLatin1Char(' ')), true);
    });
}

Result<void> ScopePage::rebuildSource()
{
    // Every channel of the page, with its scaling, on the device it was added from (the
    // current connection for channels whose device is gone): polling channels at their rate,
    // PDO channels from their PDO. One polling and one PDO source per device; the recorder's
    // channel order is kept.
    struct Sources
    {
        DeviceConnection *connection = nullptr;
        scope::PollingSource *polling = nullptr;
        scope::PdoSource *pdo = nullptr;
    };
    QList<Sources> made;
    const auto cleanUp = [&made] {
        for (const Sources &m : std::as_const(made)) {
            delete m.polling;
            delete m.pdo;
        }
    };
    const auto sourcesFor = [this, &made](DeviceConnection *c) -> Sources & {
        for (Sources &m : made) {
            if (m.connection == c)
                return m;
        }
        made.append({ c, new scope::PollingSource(c, this),
                      canopen::networkNodeOf(c) ? new scope::PdoSource(c, this) : nullptr });
        return made.last();
    };
    QList<std::pair<scope::TraceSource *, int>> order;
    QSet<QString> keys;
    for (int i = 0; i < m_recorder->channelCount(); ++i) {
        scope::ChannelInfo info = m_recorder->channelInfo(i);
        const QString oldKey = ScopeChannelModel::key(info);
        const std::optional<scope::PdoSource::Mapping> mapping = [&] {
            const auto it = m_pdoMappings.constFind(pdoKey(info.device, info.id));
            return it == m_pdoMappings.cend() ? std::nullopt : std::make_optional(it->mapping);
        }();
        DeviceConnection *connection = connectionOf(info);
        if (!connection)
            connection = m_connection;
        if (!connection->isConnected()) {
            cleanUp();
            return Error(Error::Kind::InvalidArgument,
                         tr("%1 is not connected: connect it or remove its channels")
                             .arg(deviceName(connection)));
        }
        info.device = connection->uri().toString();
        info.deviceName = deviceName(connection);
        if (keys.contains(ScopeChannelModel::key(info))) {
            cleanUp();
            return Error(Error::Kind::InvalidArgument,
                         tr("%1 would be recorded twice from %2: remove one")
                             .arg(info.displayLabel(), info.deviceName));
        }
        keys.insert(ScopeChannelModel::key(info));
        Sources &sources = sourcesFor(connection);
        Result<int> added = 0;
        if (mapping && !sources.pdo) {
            added =
                Error(Error::Kind::InvalidArgument, tr("a PDO channel needs a CANopen connection"));
        } else if (mapping) {
            info.sourceRateMs = mapping->expectedPeriodMs;
            added = sources.pdo->addChannel(info, *mapping);
        } else {
            info.sourceRateMs = m_model->rateMs(oldKey, info.sourceRateMs);
            m_model->setRateMs(ScopeChannelModel::key(info), info.sourceRateMs);
            added = sources.polling->addChannel(info);
        }
        if (!added) {
            cleanUp();
            return added.error().prefixed(info.displayLabel());
        }
        order.append(
            { mapping ? static_cast<scope::TraceSource *>(sources.pdo) : sources.polling, *added });
    }
    m_recorder->removeAllChannels();
    delete m_source;
    delete m_pdoSource;
    for (const QPointer<scope::TraceSource> &source : std::as_const(m_otherSources))
        delete source.data();
    m_otherSources.clear();
    for (const Sources &m : std::as_const(made)) {
        if (m.connection == m_connection) {
            m_source = m.polling;
            m_pdoSource = m.pdo;
        } else {
            m_otherSources.append(m.polling);
            m_otherSources.append(m.pdo);
        }
    }
    for (const auto &[source, index] : std::as_const(order))
        m_recorder->addChannel(source, index);
    return {};
}

} // namespace db::widgets
