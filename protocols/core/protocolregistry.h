#pragma once

#include "connectionuri.h"
#include "deviceconnection.h"

#include <functional>
#include <memory>

namespace db {

// What the registry knows of one URI scheme.
struct ProtocolInfo
{
    QString scheme; // URI scheme, e.g. "refgo", "canopen+slcan"
    QString key; // stable protocol key, e.g. "refgo", "canopen"
    QString title; // for people: "MovingCap RefGo (ASCII over TCP)"
    QString uriPattern; // "refgo://HOST[:PORT]"
    int defaultPort = -1;
    // Makes an unopened connection for a checked URI (default port already applied).
    std::function<std::unique_ptr<DeviceConnection>(const ConnectionUri &uri)> create;
    // Optional: refuses URIs the factory cannot serve (missing ?node=, unreadable eds=, ...),
    // so that the GUI and CLI show the cause before anything is opened.
    std::function<Result<void>(const ConnectionUri &uri)> check;
};

// Maps URI schemes to connection factories. Filled in one place (app/), passed to whoever
// needs to make connections; not a singleton.
class ProtocolRegistry
{
public:
    void add(const ProtocolInfo &info);
    const ProtocolInfo *find(const QString &scheme) const;
    const QList<ProtocolInfo> &protocols() const { return m_protocols; }

    // Syntax + known scheme + default port.
    Result<ConnectionUri> parseUri(const QString &text) const;
    // parseUri() + the protocol's factory.
    Result<std::shared_ptr<DeviceConnection>> create(const QString &text) const;

private:
    QList<ProtocolInfo> m_protocols;
};

} // namespace db
