#include "error.h"

#include "printable.h"

namespace db {

Error::Error(Kind kind, QString message, quint32 deviceCode)
    : m_kind(kind)
    , m_message(printable(message))
    , m_deviceCode(deviceCode)
{ }

QString Error::kindName(Kind kind)
{
    switch (kind) {
    case Kind::None:
        return QStringLiteral("ok");
    case Kind::InvalidArgument:
        return QStringLiteral("invalid argument");
    case Kind::OutOfRange:
        return QStringLiteral("out of range");
    case Kind::AccessDenied:
        return QStringLiteral("access denied");
    case Kind::NotSupported:
        return QStringLiteral("not supported");
    case Kind::ConnectionRefused:
        return QStringLiteral("connection refused");
    case Kind::HostNotFound:
        return QStringLiteral("host not found");
    case Kind::Timeout:
        return QStringLiteral("timeout");
    case Kind::Disconnected:
        return QStringLiteral("disconnected");
    case Kind::Malformed:
        return QStringLiteral("malformed answer");
    case Kind::DeviceError:
        return QStringLiteral("device error");
    case Kind::Cancelled:
        return QStringLiteral("cancelled");
    case Kind::Io:
        return QStringLiteral("i/o error");
    case Kind::Busy:
        return QStringLiteral("busy");
    }
    return QStringLiteral("error");
}

QString Error::toString() const
{
    if (m_message.isEmpty())
        return kindName(m_kind);
    return kindName(m_kind) + QStringLiteral(": ") + m_message;
}

Error Error::prefixed(const QString &context) const
{
    Error copy = *this;
    copy.m_message = printable(context) + QStringLiteral(": ") + m_message;
    return copy;
}

} // namespace db
