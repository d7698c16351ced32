#pragma once

// Device peers served by the test process on 127.0.0.1 and OS-chosen ports, for the failure
// paths of clients and command-line tools: raw peers (silent, garbage, flooding SLCAN), a RefGo
// drive whose reads go wrong in one chosen way, and a CANopen node behind SLCAN over TCP that
// aborts every SDO. A tool under test must run while the test's event loop turns: use
// runServing() (clirun.h), not runProgram().

#include "transport/slcancodec.h"

#include <QByteArray>
#include <QList>
#include <QSet>
#include <QTcpServer>
#include <QTimer>

class QTcpSocket;

namespace db::test {

// A loopback port that was free a moment ago (bound by the OS, then released): nothing listens.
quint16 closedLoopbackPort();

// Listens on 127.0.0.1 (an OS-chosen port) from construction; hands every chunk of received
// bytes to serve(). Connected sockets are closed before the peer goes.
class LoopbackPeer : public QTcpServer
{
public:
    explicit LoopbackPeer(QObject *parent = nullptr);
    ~LoopbackPeer() override;

    quint16 port() const { return serverPort(); }

protected:
    virtual void serve(QTcpSocket *socket, const QByteArray &bytes) = 0;
    virtual void accepted(QTcpSocket *) { }
    const QList<QTcpSocket *> &sockets() const { return m_sockets; }

private:
    void accept();

    QList<QTcpSocket *> m_sockets;
};

// Accepts and then never answers (Silent), answers every chunk received with `answer`
// (Garbage), or floods valid SLCAN frames of other nodes from the moment it is connected.
class RawPeer : public LoopbackPeer
{
public:
    enum class Behaviour { Silent, Garbage, Flood };

    explicit RawPeer(Behaviour behaviour, QByteArray answer = {}, QObject *parent = nullptr);

    qint64 framesSent() const { return m_framesSent; }

protected:
    void serve(QTcpSocket *socket, const QByteArray &bytes) override;
    void accepted(QTcpSocket *socket) override;

private:
    // A flood well above a real 1 Mbit/s bus, bounded by what the socket has not sent yet.
    static constexpr int kFramesPerTick = 200;
    static constexpr qint64 kMaxUnsent = 256 * 1024;

    void flood();

    Behaviour m_behaviour;
    QByteArray m_answer;
    QTimer m_flood;
    qint64 m_framesSent = 0;
};

// A RefGo drive (echo CR LF, result lines CR LF, '>') that answers every OR with value 0 and
// every OW with OK, except for the objects in `faulty` (all objects when empty), whose reads go
// wrong as `fault` says.
class HostileRefgoPeer : public LoopbackPeer
{
public:
    enum class Fault {
        None,
        PreviousAnswer, // the answer to the previous request (echo and all): one answer behind
        Error, // "ERROR <reason>"
        NulByte, // a NUL byte inside the value
        HugeValue, // a value beyond 64 bits
        OutOfRange, // a value that fits 64 bits but not the object's type
        OtherObject, // the right echo, but the result line names another object
    };

    explicit HostileRefgoPeer(Fault fault, QSet<QString> faulty = {});

    QString uri() const;
    int requests() const { return m_requests; }

protected:
    void serve(QTcpSocket *socket, const QByteArray &bytes) override;

private:
    static constexpr qsizetype kMaxLine = 256;

    QByteArray answer(const QByteArray &line);

    Fault m_fault;
    QSet<QString> m_faulty;
    QByteArray m_buffer;
    QByteArray m_previous;
    int m_requests = 0;
};

// An SLCAN adapter over TCP with one CANopen node behind it whose SDO server aborts every
// request (CiA 301 7.2.4.3.17: ccs 4, the request's index and sub-index, the abort code
// little-endian). Commands (C, S4, O) are acknowledged with CR.
class AbortingSlcanPeer : public LoopbackPeer
{
public:
    explicit AbortingSlcanPeer(quint8 node, quint32 abortCode = 0x06020000);

    QString uri() const;
    int aborts() const { return m_aborts; }

protected:
    void serve(QTcpSocket *socket, const QByteArray &bytes) override;

private:
    quint8 m_node;
    quint32 m_abortCode;
    slcan::Decoder m_decoder;
    int m_aborts = 0;
};

} // namespace db::test
