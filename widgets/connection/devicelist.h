#pragma once

#include "core/deviceconnection.h"

#include <QPointer>
#include <QWidget>

class QListWidget;
class QListWidgetItem;
class QToolButton;

namespace db::widgets {

// The open connections with their URI and state. Selecting one makes it current. It does not
// own the connections: it asks its owner to connect, disconnect, add or remove through the
// *Requested signals, and forgets a connection that is destroyed.
class DeviceList : public QWidget
{
    Q_OBJECT
public:
    explicit DeviceList(QWidget *parent = nullptr);

    void addConnection(DeviceConnection *connection);
    void removeConnection(DeviceConnection *connection);
    QList<DeviceConnection *> connections() const;
    int count() const;

    DeviceConnection *currentConnection() const;
    void setCurrentConnection(DeviceConnection *connection);

Q_SIGNALS:
    void currentConnectionChanged(db::DeviceConnection *connection);
    void addRequested();
    void connectRequested(db::DeviceConnection *connection);
    void disconnectRequested(db::DeviceConnection *connection);
    void removeRequested(db::DeviceConnection *connection);

private:
    QListWidgetItem *itemFor(const DeviceConnection *connection) const;
    void updateItem(QListWidgetItem *item);
    void updateActions();

    QListWidget *m_list;
    QToolButton *m_addButton;
    QToolButton *m_connectButton;
    QToolButton *m_disconnectButton;
    QToolButton *m_removeButton;
};

} // namespace db::widgets
