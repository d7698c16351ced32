#pragma once

// Hostile device peers served by the test process on 127.0.0.1 (OS-chosen ports), for the
// failure paths of the command-line tools: a RefGo drive whose object reads go wrong in one
// chosen way, and a CANopen node behind SLCAN over TCP that aborts every SDO. Run the tool with
// runServing() so that the peers answer. Header-only.
#include "transport/slcancodec.h"

#include <QHostAddress>
#include <QRegularExpression>
#include <QSet>
#include <QTcpServer>
#include <QTcpSocket>

namespace db::test {

// A RefGo drive (movingcap.md 3.1 framing: echo CR LF, result lines CR LF, '>') that answers
// every OR with value 0 and every OW with OK, except for the objects in `faulty` (all objects
// when empty), whose reads go wrong as `fault` says.
class HostileRefgoPeer : public QTcpServer
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

    explicit HostileRefgoPeer(Fault fault, QSet<QString> faulty = {})
        : m_fault(fault)
        , m_faulty(std::move(faulty))
    {
        listen(QHostAddress::LocalHost, 0);
        connect(this, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *socket = nextPendingConnection()) {
                connect(socket, &QTcpSocket::readyRead, this, [this, socket] { serve(socket); });
                connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
            }
        });
    }

    QString uri() const { return QStringLiteral("refgo://127.0.0.1:%1").arg(serverPort()); }
    int requests() const { return m_requests; }

private:
    static constexpr qsizetype kMaxLine = 256;

    void serve(QTcpSocket *socket)
    {
        m_buffer += socket->readAll();
        m_buffer.replace('\n', QByteArray());
        qsizetype cr;
        while ((cr = m_buffer.indexOf('\r')) >= 0) {
            const QByteArray line = m_buffer.left(cr);
            m_buffer.remove(0, cr + 1);
            if (!line.isEmpty())
                socket->write(answer(line));
        }
        if (m_buffer.size() > kMaxLine)
            m_buffer.clear();
    }

    // "OR6083,0" -> "6083,0" (the object as "INDEX,SUB"); empty for other commands.
    static QByteArray objectOf(const QByteArray &line)
    {
        static const QRegularExpression re(
            QStringLiteral("^O[RW]\\s*([0-9A-Fa-f]+),([0-9A-Fa-f]+)"));
        const auto m = re.match(QString::fromLatin1(line));
        return m.hasMatch() ? (m.captured(1) + u',' + m.captured(2)).toLatin1() : QByteArray();
    }

    QByteArray healthy(const QByteArray &line) const
    {
        if (line.startsWith("OW"))
            return line + "\r\n" + line + ",OK\r\n>";
        if (line.startsWith("OR"))
            return line + "\r\nOR" + objectOf(line) + ",0\r\n>";
        return line + "\r\n>";
    }

    QByteArray answer(const QByteArray &line)
    {
        ++m_requests;
        const QByteArray object = objectOf(line);
        const QByteArray good = healthy(line);
        const bool faulty = line.startsWith("OR")
            && (m_faulty.isEmpty() || m_faulty.contains(QString::fromLatin1(object)));
        QByteArray out = good;
        if (faulty) {
            switch (m_fault) {
            case Fault::None:
                break;
            case Fault::PreviousAnswer:
                out = m_previous.isEmpty() ? good : m_previous;
                break;
            case Fault::Error:
                out = line + "\r\nERROR object not available\r\n>";
                break;
            case Fault::NulByte:
                out = line + "\r\nOR" + object + ",12" + QByteArray(1, '\0') + "34\r\n>";
                break;
            case Fault::HugeValue:
                out = line + "\r\nOR" + object + ",99999999999999999999999999999999\r\n>";
                break;
            case Fault::OutOfRange:
                out = line + "\r\nOR" + object + ",-9000000000000000000\r\n>";
                break;
            case Fault::OtherObject:
                out = line + "\r\nOR" + (object == "6083,0" ? "6084,0" : "6083,0") + ",7\r\n>";
                break;
            }
        }
        m_previous = good;
        return out;
    }

    Fault m_fault;
    QSet<QString> m_faulty;
    QByteArray m_buffer;
    QByteArray m_previous;
    int m_requests = 0;
};

// An SLCAN adapter over TCP (movingcap.md 4.2) with one CANopen node behind it whose SDO server
// aborts every request (CiA 301 7.2.4.3.17: ccs 4, the request's index and sub-index, the abort
// code little-endian). Commands (C, S4, O) are acknowledged with CR.
class AbortingSlcanPeer : public QTcpServer
{
public:
    explicit AbortingSlcanPeer(quint8 node, quint32 abortCode = 0x06020000)
        : m_node(node)
        , m_abortCode(abortCode)
    {
        listen(QHostAddress::LocalHost, 0);
        connect(this, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *socket = nextPendingConnection()) {
                connect(socket, &QTcpSocket::readyRead, this, [this, socket] { serve(socket); });
                connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
            }
        });
    }

    QString uri() const
    {
        return QStringLiteral("canopen+slcan://127.0.0.1:%1?node=%2").arg(serverPort()).arg(m_node);
    }
    int aborts() const { return m_aborts; }

private:
    void serve(QTcpSocket *socket)
    {
        for (const slcan::Message &m : m_decoder.feed(socket->readAll())) {
            if (m.kind == slcan::Message::Kind::Command) {
                socket->write(QByteArray(1, slcan::kCr));
                continue;
            }
            if (m.kind != slcan::Message::Kind::Frame || m.frame.frameId() != 0x600u + m_node
                || m.frame.payload().size() != 8)
                continue;
            const QByteArray request = m.frame.payload();
            QByteArray abort(8, '\0');
            abort[0] = char(0x80);
            abort[1] = request[1];
            abort[2] = request[2];
            abort[3] = request[3];
            for (int i = 0; i < 4; ++i)
                abort[4 + i] = char((m_abortCode >> (8 * i)) & 0xFF);
            ++m_aborts;
            socket->write(slcan::encodeFrame(QCanBusFrame(0x580u + m_node, abort)));
        }
    }

    quint8 m_node;
    quint32 m_abortCode;
    slcan::Decoder m_decoder;
    int m_aborts = 0;
};

} // namespace db::test
