#pragma once

// Device side of RefGo (used by the simulators): a TCP server on loopback that frames requests
// (one line per CR) and answers "<echo>\r\n<result lines>\r\n...>" exactly as movingcap.md 3.1
// and 3.8 show. Every client is throttled (ClientThrottle): one that does not read its answers
// is paused and finally dropped, and cannot starve the others.

#include "refgo/refgocodec.h"
#include "transport/clientthrottle.h"

#include <QHostAddress>
#include <QObject>
#include <QStringList>

class QTcpServer;
class QTcpSocket;

namespace db::refgo {

// What a simulated device answers to one parsed request: its result lines (without CR LF).
// A request that parseRequest() refused is answered by the server itself.
class DeviceHandler
{
public:
    virtual ~DeviceHandler() = default;
    virtual QStringList handle(const Request &request) = 0;
};

class Server : public QObject
{
    Q_OBJECT
public:
    // The handler must outlive the server.
    explicit Server(DeviceHandler *handler, QObject *parent = nullptr);
    ~Server() override;

    // Listens on address:port (port 0 = chosen by the OS). Loopback only by default.
    Result<void> listen(quint16 port = 0, const QHostAddress &address = QHostAddress::LocalHost);
    quint16 port() const;
    void close();
    // Aborts every client connection (RST, no goodbye) and keeps listening: a cut cable as the
    // clients see it. Returns how many were dropped.
    int dropClients();
    int clientCount() const;
    // While on, requests are read and dropped unanswered: a device that hangs with its link up.
    void setSilent(bool on);
    // Applies to clients that connect afterwards.
    void setClientLimits(const ClientThrottle::Limits &limits);
    // The longest output queue (unread answers) any client had so far, in bytes.
    qint64 peakQueuedBytes() const;

Q_SIGNALS:
    void requestHandled(const QString &request, const QStringList &result);

private:
    class Private;
    Private *d;
};

} // namespace db::refgo
