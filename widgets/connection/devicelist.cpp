#include "devicelist.h"

#include "widgets/common/flowlayout.h"

#include "widgets/common/widgetstyle.h"

#include <QListWidget>
#include <QToolButton>
#include <QVBoxLayout>

namespace db::widgets {

namespace {
constexpr int kConnectionRole = Qt::UserRole + 1;

DeviceConnection *connectionOf(const QListWidgetItem *item)
{
    if (!item)
        return nullptr;
    const auto pointer = item->data(kConnectionRole).value<QPointer<QObject>>();
    return qobject_cast<DeviceConnection *>(pointer.data());
}

QToolButton *makeButton(const QString &text, const QString &toolTip, QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setText(text);
    button->setToolTip(toolTip);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    button->setAutoRaise(false);
    return button;
}
} // namespace

DeviceList::DeviceList(QWidget *parent)
    : QWidget(parent)
    , m_list(new QListWidget(this))
    , m_addButton(makeButton(tr("Add…"), tr("Open a new connection"), this))
    , m_connectButton(makeButton(tr("Connect"), tr("Connect the selected device"), this))
    , m_disconnectButton(makeButton(tr("Disconnect"), tr("Disconnect the selected device"), this))
    , m_removeButton(makeButton(tr("Remove"), tr("Close and remove the selected device"), this))
{
    m_list->setObjectName(QStringLiteral("deviceListView"));
    m_list->setSelectionMode(QAbstractItemView::SingleSelection);
    m_list->setIconSize(QSize(16, 16));
    m_list->setUniformItemSizes(true);

    auto *buttons = new FlowLayout; // wraps when the dock is narrow (long translations)
    buttons->setSpacing(4);
    buttons->addWidget(m_addButton);
    buttons->addWidget(m_connectButton);
    buttons->addWidget(m_disconnectButton);
    buttons->addWidget(m_removeButton);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_list);
    layout->addLayout(buttons);

    connect(m_list, &QListWidget::currentItemChanged, this, [this](QListWidgetItem *item) {
        updateActions();
        Q_EMIT currentConnectionChanged(connectionOf(item));
    });
    connect(m_addButton, &QToolButton::clicked, this, &DeviceList::addRequested);
    connect(m_connectButton, &QToolButton::clicked, this, [this] {
        if (DeviceConnection *c = currentConnection())
            Q_EMIT connectRequested(c);
    });
    connect(m_disconnectButton, &QToolButton::clicked, this, [this] {
        if (DeviceConnection *c = currentConnection())
            Q_EMIT disconnectRequested(c);
    });
    connect(m_removeButton, &QToolButton::clicked, this, [this] {
        if (DeviceConnection *c = currentConnection())
            Q_EMIT removeRequested(c);
    });
    updateActions();
}

void DeviceList::addConnection(DeviceConnection *connection)
{
    if (!connection || itemFor(connection))
        return;
    auto *item = new QListWidgetItem(m_list);
    item->setData(kConnectionRole, QVariant::fromValue(QPointer<QObject>(connection)));
    updateItem(item);
    connect(connection, &DeviceConnection::stateChanged, this, [this, connection] {
        if (QListWidgetItem *i = itemFor(connection))
            updateItem(i);
        updateActions();
    });
    if (ConnectionHealth *health = ConnectionHealth::of(connection)) {
        connect(health, &ConnectionHealth::statusChanged, this, [this, connection] {
            if (QListWidgetItem *i = itemFor(connection))
                updateItem(i);
        });
    }
    connect(connection, &QObject::destroyed, this, [this](QObject *object) {
        for (int row = 0; row < m_list->count(); ++row) {
            QListWidgetItem *i = m_list->item(row);
            const auto p = i->data(kConnectionRole).value<QPointer<QObject>>();
            if (!p || p.data() == object) {
                delete i;
                break;
            }
        }
        updateActions();
    });
    if (!m_list->currentItem())
        m_list->setCurrentItem(item);
    updateActions();
}

void DeviceList::removeConnection(DeviceConnection *connection)
{
    if (QListWidgetItem *item = itemFor(connection)) {
        disconnect(connection, nullptr, this, nullptr);
        delete item; // currentItemChanged follows when it was current
    }
    updateActions();
}

QList<DeviceConnection *> DeviceList::connections() const
{
    QList<DeviceConnection *> result;
    for (int row = 0; row < m_list->count(); ++row) {
        if (DeviceConnection *c = connectionOf(m_list->item(row)))
            result.append(c);
    }
    return result;
}

int DeviceList::count() const
{
    return m_list->count();
}

DeviceConnection *DeviceList::currentConnection() const
{
    return connectionOf(m_list->currentItem());
}

void DeviceList::setCurrentConnection(DeviceConnection *connection)
{
    m_list->setCurrentItem(itemFor(connection));
}

QListWidgetItem *DeviceList::itemFor(const DeviceConnection *connection) const
{
    if (!connection)
        return nullptr;
    for (int row = 0; row < m_list->count(); ++row) {
        if (connectionOf(m_list->item(row)) == connection)
            return m_list->item(row);
    }
    return nullptr;
}

void DeviceList::updateItem(QListWidgetItem *item)
{
    DeviceConnection *c = connectionOf(item);
    if (!c)
        return;
    const DeviceConnection::State state = c->state();
    item->setText(c->uri().toString());
    const ConnectionHealth *health = ConnectionHealth::of(c);
    item->setIcon(health ? style::healthIcon(health->status()) : style::connectionStateIcon(state));
    QString tip = tr("%1\nState: %2")
                      .arg(c->uri().toString(), health ? health->description() : stateName(state));
    if (c->lastError().isError())
        tip += tr("\nLast error: %1").arg(c->lastError().toString());
    item->setToolTip(tip);
}

void DeviceList::updateActions()
{
    DeviceConnection *c = currentConnection();
    const auto state = c ? c->state() : DeviceConnection::State::Disconnected;
    m_connectButton->setEnabled(c && state == DeviceConnection::State::Disconnected);
    m_disconnectButton->setEnabled(c
                                   && (state == DeviceConnection::State::Connected
                                       || state == DeviceConnection::State::Connecting));
    m_removeButton->setEnabled(c != nullptr);
}

} // namespace db::widgets
