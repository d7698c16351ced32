#include "networkview.h"

#include "canopen/cannetwork.h"
#include "canopen/syncproducer.h"
#include "lsspanel.h"
#include "nodelist.h"
#include "pdopanel.h"
#include "widgets/common/widgetstyle.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QVBoxLayout>

namespace db::widgets {

NetworkView::NetworkView(QWidget *parent)
    : QWidget(parent)
    , m_title(new QLabel(this))
    , m_nodes(new NodeList(this))
    , m_sync(new QCheckBox(tr("SYNC producer"), this))
    , m_syncPeriod(new QSpinBox(this))
    , m_tools(new QTabWidget(this))
    , m_pdo(new PdoPanel(this))
    , m_lss(new LssPanel(this))
{
    setObjectName(QStringLiteral("networkView"));
    m_title->setObjectName(QStringLiteral("networkTitle"));
    m_sync->setObjectName(QStringLiteral("syncOn"));
    m_syncPeriod->setObjectName(QStringLiteral("syncPeriod"));
    m_tools->setObjectName(QStringLiteral("networkTools"));
    m_sync->setToolTip(tr("Send SYNC (080h) on this bus every period; synchronous PDOs follow it"));
    m_syncPeriod->setRange(1, 10000);
    m_syncPeriod->setValue(100);
    m_syncPeriod->setSuffix(tr(" ms"));
    m_syncPeriod->setToolTip(tr("SYNC period (communication cycle)"));

    auto *syncRow = new QHBoxLayout;
    syncRow->setContentsMargins(4, 0, 4, 4);
    syncRow->addWidget(m_sync);
    syncRow->addWidget(m_syncPeriod);
    syncRow->addStretch(1);
    auto *left = new QWidget(this);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->setSpacing(2);
    leftLayout->addWidget(m_nodes, 1);
    leftLayout->addLayout(syncRow);

    m_tools->addTab(m_pdo, tr("PDO mapping"));
    m_tools->addTab(m_lss, tr("LSS"));
    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setChildrenCollapsible(false);
    splitter->addWidget(left);
    splitter->addWidget(m_tools);
    splitter->setStretchFactor(0, 2);
    splitter->setStretchFactor(1, 3);
    splitter->setSizes({ 400, 600 }); // the PDO mapping needs the room

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_title);
    layout->addWidget(splitter, 1);

    connect(m_nodes, &NodeList::selectedNodeChanged, m_pdo, &PdoPanel::setNode);
    connect(m_sync, &QCheckBox::toggled, this, [this](bool on) {
        if (on != isSyncOn())
            setSync(on);
    });
    connect(m_syncPeriod, &QSpinBox::valueChanged, this, [this] {
        if (isSyncOn())
            setSync(true); // restarts with the new period
    });
    setNetwork(nullptr);
}

NetworkView::~NetworkView() = default;

void NetworkView::setChangeLog(ChangeLog *log)
{
    m_pdo->setChangeLog(log);
    m_lss->setChangeLog(log);
    m_nodes->setChangeLog(log);
}

canopen::CanNetwork *NetworkView::network() const
{
    return m_network;
}

void NetworkView::setConnection(DeviceConnection *connection)
{
    const canopen::NetworkNode at = canopen::networkNodeOf(connection);
    if (!at) {
        setNetwork(nullptr);
        return;
    }
    const DeviceIdentity &id = connection->dictionary().identity;
    setNetwork(at.network, at.node, id.productName.isEmpty() ? id.vendorName : id.productName);
}

void NetworkView::setNetwork(canopen::CanNetwork *network, canopen::NodeId ownNode,
                             const QString &ownName)
{
    m_network = network;
    m_nodes->setNetwork(network, ownNode, ownName);
    m_pdo->setNetwork(network);
    m_pdo->setNode(m_nodes->targetNode() > 0 ? canopen::NodeId(m_nodes->targetNode()) : 0);
    m_lss->setNetwork(network);
    m_title->setText(network ? tr("CANopen network on %1").arg(network->name())
                             : tr("No CANopen connection: connect to a CANopen node to see its "
                                  "network."));
    updateSync();
}

bool NetworkView::setSync(bool on)
{
    if (!m_network)
        return false;
    canopen::SyncProducer *sync = m_network->sync();
    if (!on) {
        sync->stop();
    } else {
        if (!m_network->isOpen())
            return false;
        sync->start(m_syncPeriod->value());
    }
    updateSync();
    return true;
}

void NetworkView::setSyncPeriodMs(int ms)
{
    m_syncPeriod->setValue(ms);
}

bool NetworkView::isSyncOn() const
{
    return m_network && m_network->sync()->isRunning();
}

void NetworkView::updateSync()
{
    const QSignalBlocker blocker(m_sync);
    m_sync->setChecked(isSyncOn());
    m_sync->setEnabled(m_network);
    if (isSyncOn()) {
        const QSignalBlocker periodBlocker(m_syncPeriod);
        m_syncPeriod->setValue(m_network->sync()->periodMs());
    }
}

} // namespace db::widgets
