#pragma once

#include "result.h"

#include <QMap>
#include <QString>

namespace db {

// A connection address, the same in GUI, CLI and settings:
//   refgo://HOST[:PORT]                      MovingCap RefGo ASCII, default port 10001
//   canopen+slcan://HOST[:PORT]?node=N       CANopen over SLCAN tunnelled in TCP, default 15001
//   canopen+socketcan://IFACE?node=N&bitrate=B
//   canopen+virtualcan://IFACE?node=N
//   vabus://HOST[:PORT]                      Bonfiglioli VABus/TCP, default 17220
// Parsing checks syntax only; ProtocolRegistry::parseUri() also checks the scheme and fills in
// the protocol's default port.
class ConnectionUri
{
public:
    static Result<ConnectionUri> parse(const QString &text);

    QString scheme() const { return m_scheme; }
    QString host() const { return m_host; }
    int port() const { return m_port; } // -1 when not given
    int portOr(int fallback) const { return m_port >= 0 ? m_port : fallback; }
    void setPort(int port) { m_port = port; }
    QMap<QString, QString> query() const { return m_query; }
    QString queryValue(const QString &key) const { return m_query.value(key); }
    void setQueryValue(const QString &key, const QString &value) { m_query.insert(key, value); }
    bool hasQuery(const QString &key) const { return m_query.contains(key); }
    // A query parameter as an integer in [min, max]; InvalidArgument names the parameter.
    Result<int> queryInt(const QString &key, int min, int max) const;

    // Canonical text: scheme://host[:port][?k=v&...] (query keys sorted).
    QString toString() const;

    friend bool operator==(const ConnectionUri &, const ConnectionUri &) = default;

private:
    QString m_scheme;
    QString m_host;
    int m_port = -1;
    QMap<QString, QString> m_query;
};

} // namespace db
