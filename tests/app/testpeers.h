#pragma once

// Hostile device peers for the command-line tests, in the test's own event loop on 127.0.0.1 and
// an OS-chosen port: one that accepts and never answers, one that answers every request with
// bytes that break the protocol, one that floods SLCAN frames from the moment it is connected.
// The tool under test must run while the loop turns: use runServing() (clirun.h), not
// runProgram(). Header-only.
#include <QByteArray>
#include <QHostAddress>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

#include <utility>

namespace db::test {

class TestPeer : public QObject
{
public:
    enum class Behaviour { Silent, Garbage, Flood };

    // Garbage: `answer` is sent for every chunk of bytes received.
    explicit TestPeer(Behaviour behaviour, QByteArray answer = {}, QObject *parent = nullptr)
        : QObject(parent)
        , m_behaviour(behaviour)
        , m_answer(std::move(answer))
    {
        m_flood.setInterval(1);
        QObject::connect(&m_flood, &QTimer::timeout, this, &TestPeer::flood);
        QObject::connect(&m_server, &QTcpServer::newConnection, this, &TestPeer::accept);
    }

    // The connections go first: they refer to this peer.
    ~TestPeer() override
    {
        m_flood.stop();
        for (QTcpSocket *s : std::exchange(m_sockets, {})) {
            s->disconnect(this);
            delete s;
        }
    }

    bool listen() { return m_server.listen(QHostAddress::LocalHost, 0); }
    quint16 port() const { return m_server.serverPort(); }
    qint64 framesSent() const { return m_framesSent; }

private:
    // A flood well above a real 1 Mbit/s bus, bounded by what the socket has not sent yet.
    static constexpr int kFramesPerTick = 200;
    static constexpr qint64 kMaxUnsent = 256 * 1024;

    void accept()
    {
        while (QTcpSocket *s = m_server.nextPendingConnection()) {
            m_sockets.append(s);
            QObject::connect(s, &QTcpSocket::disconnected, s, &QObject::deleteLater);
            QObject::connect(s, &QObject::destroyed, this, [this, s] { m_sockets.removeAll(s); });
            QObject::connect(s, &QTcpSocket::readyRead, s, [this, s] {
                s->readAll();
                if (m_behaviour == Behaviour::Garbage)
                    s->write(m_answer);
            });
        }
        if (m_behaviour == Behaviour::Flood && !m_flood.isActive())
            m_flood.start();
    }

    void flood()
    {
        for (QTcpSocket *s : std::as_const(m_sockets)) {
            if (s->bytesToWrite() > kMaxUnsent)
                continue;
            QByteArray chunk;
            for (int i = 0; i < kFramesPerTick; ++i) {
                // PDO-like frames of other nodes: valid SLCAN, never an answer to a request.
                chunk += "t1"
                    + QByteArray::number(0x80 + (m_framesSent % 0x7F), 16).rightJustified(2, '0')
                    + "8" + QByteArray::number(m_framesSent, 16).rightJustified(16, '0').right(16)
                    + '\r';
                ++m_framesSent;
            }
            s->write(chunk);
        }
    }

    Behaviour m_behaviour;
    QByteArray m_answer;
    QTcpServer m_server;
    QList<QTcpSocket *> m_sockets;
    QTimer m_flood;
    qint64 m_framesSent = 0;
};

} // namespace db::test
