#include "error.h"

#include "printable.h"

namespace db {

Error::Error(Kind kind, QString message, quint32 deviceCode)
    : m_kind(kind)
    , m_message(isPrintable(message) ? std::move(message) : printable(message))
    , m_deviceCode(deviceCode)
{ }

QString Error::kindName(Kind kind)
{
    switch (kind) {
    case Kind::None:
        return tr("ok");
    case Kind::InvalidArgument:
        return tr("invalid argument");
    case Kind::OutOfRange:
        return tr("out of range");
    case Kind::AccessDenied:
        return tr("access denied");
    case Kind::NotSupported:
        return tr("not supported");
    case Kind::ConnectionRefused:
        return tr("connection refused");
    case Kind::HostNotFound:
        return tr("host not found");
    case Kind::Timeout:
        return tr("timeout");
    case Kind::Disconnected:
        return tr("disconnected");
    case Kind::Malformed:
        // Device answers and files alike (a file's errors also name the file and line).
        return tr("malformed data");
    case Kind::DeviceError:
        return tr("device error");
    case Kind::Cancelled:
        return tr("cancelled");
    case Kind::Io:
        return tr("i/o error");
    case Kind::Busy:
        return tr("busy");
    }
    return tr("error");
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
