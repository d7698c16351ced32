#pragma once

#include <QCoreApplication>
#include <QMetaType>
#include <QString>

namespace db {

// What went wrong, in a form that both code (kind, deviceCode) and people (message) can use.
// Errors are values: they cross the event loop in replies and signals, never as exceptions.
class Error
{
    Q_DECLARE_TR_FUNCTIONS(db::Error)

public:
    enum class Kind {
        None,
        InvalidArgument, // user input that cannot be used (bad address, value, URI)
        OutOfRange, // value outside the type's or the object's range
        AccessDenied, // read-only object written, write-only object read
        NotSupported, // the protocol or device cannot do this
        ConnectionRefused, // nobody listens at the address
        HostNotFound,
        Timeout, // no answer within the request's time limit
        Disconnected, // the link went away while the request was pending
        Malformed, // the device's answer breaks the protocol (garbage, wrong echo)
        DeviceError, // the device answered with an error (SDO abort, missing ",OK")
        Cancelled,
        Io, // files and sockets
        Busy,
    };

    Error() = default;
    // The message is kept with its control characters escaped (printable(), one line): it
    // often quotes a device's answer, a file's contents or a file name, and it ends up on a
    // terminal, in the log console or in a report.
    Error(Kind kind, QString message, quint32 deviceCode = 0);

    Kind kind() const { return m_kind; }
    bool isError() const { return m_kind != Kind::None; }
    // The protocol's own code, e.g. a CANopen SDO abort code; 0 when there is none.
    quint32 deviceCode() const { return m_deviceCode; }
    const QString &message() const { return m_message; }

    // "timeout: no answer to 'TP' from 127.0.0.1:10001 within 1000 ms"
    QString toString() const;
    static QString kindName(Kind kind);

    // A copy with context put in front of the message ("reading 6041:0: ..."), the context
    // escaped like the message.
    Error prefixed(const QString &context) const;

    friend bool operator==(const Error &, const Error &) = default;

private:
    Kind m_kind = Kind::None;
    QString m_message;
    quint32 m_deviceCode = 0;
};

} // namespace db

Q_DECLARE_METATYPE(db::Error)
