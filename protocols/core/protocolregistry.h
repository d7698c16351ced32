#pragma once

#include "connectionuri.h"
#include "deviceconnection.h"

#include <functional>
#include <memory>

namespace db {

// Everything a connection needs, worked out once from its URI before anything is opened: the
// checked URI (default port applied), the device description it names (loaded once), and the
// time limits the transport and the engine get.
struct ConnectionPlan
{
    ConnectionUri uri;
    ObjectDictionary dictionary; // the description the URI names (?eds=), or the built-in one
    bool hasDictionary = false; // false: the protocol's factory decides
    int connectTimeoutMs = 3000;
    int requestTimeoutMs = 1000;
};

// What the registry knows of one URI scheme.
struct ProtocolInfo
{
    QString scheme; // URI scheme, e.g. "refgo", "canopen+slcan"
    QString key; // stable protocol key, e.g. "refgo", "canopen"
    QString title; // for people: "MovingCap RefGo (ASCII over TCP)"
    QString uriPattern; // "refgo://HOST[:PORT]"
    int defaultPort = -1;
    // Makes an unopened connection from a prepared plan; the error names the real cause (an
    // unknown CAN plugin, a bus in use at another bitrate, ...).
    std::function<Result<std::unique_ptr<DeviceConnection>>(const ConnectionPlan &plan)> create;
    // Optional and cheap (no files, no network): refuses URIs the factory cannot serve (missing
    // ?node=, bad bitrate, ...), so that the GUI can check as the user types.
    std::function<Result<void>(const ConnectionUri &uri)> check;
    // Optional: the rest of the plan (loads the description the URI names). Runs once per
    // connection, when the user connects.
    std::function<Result<void>(ConnectionPlan &plan)> prepare;
    // How the protocol's object addresses are written, so that the CLI can parse them before it
    // connects. Null means AddressFormat::canopen().
    const AddressFormat *addressFormat = nullptr;
};

// Maps URI schemes to connection factories. Filled in one place (app/), passed to whoever
// needs to make connections; not a singleton.
class ProtocolRegistry
{
public:
    void add(const ProtocolInfo &info);
    const ProtocolInfo *find(const QString &scheme) const;
    const QList<ProtocolInfo> &protocols() const { return m_protocols; }

    // Syntax + known scheme + default port + the protocol's cheap check.
    Result<ConnectionUri> parseUri(const QString &text) const;
    // parseUri() + the protocol's prepare(): everything create() needs. The plan starts with
    // the given time limits.
    Result<ConnectionPlan> prepare(const QString &text, int connectTimeoutMs = 3000,
                                   int requestTimeoutMs = 1000) const;
    // The protocol's factory for a prepared plan; the connection gets the plan's time limits.
    Result<std::shared_ptr<DeviceConnection>> create(const ConnectionPlan &plan) const;
    // prepare() + create(), with the default time limits.
    Result<std::shared_ptr<DeviceConnection>> create(const QString &text) const;

private:
    QList<ProtocolInfo> m_protocols;
};

} // namespace db
