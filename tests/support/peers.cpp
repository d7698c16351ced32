#include "peers.h"

#include <QHostAddress>
#include <QRegularExpression>
#include <QTcpSocket>

#include <utility>

namespace db::test {

quint16 closedLoopbackPort()
{
    QTcpServer server;
    if (!server.listen(QHostAddress::LocalHost, 0))
        return 0;
    const quint16 port = server.serverPort();
    server.close();
    return port;
}

LoopbackPeer::LoopbackPeer(QObject *parent)
    : QTcpServer(parent)
{
    connect(this, &QTcpServer::newConnection, this, &LoopbackPeer::accept);
    listen(QHostAddress::LocalHost, 0);
}

// The sockets go first: their handlers refer to this peer.
LoopbackPeer::~LoopbackPeer()
{
    for (QTcpSocket *s : std::exchange(m_sockets, {})) {
        s->disconnect(this);
        delete s;
    }
}

void LoopbackPeer::accept()
{
    while (QTcpSocket *s = nextPendingConnection()) {
        m_sockets.append(s);
        connect(s, &QTcpSocket::disconnected, s, &QObject::deleteLater);
        connect(s, &QObject::destroyed, this, [this, s] { m_sockets.removeAll(s); });
        connect(s, &QTcpSocket::readyRead, this, [this, s] { serve(s, s->readAll()); });
        accepted(s);
    }
}

RawPeer::RawPeer(Behaviour behaviour, QByteArray answer, QObject *parent)
    : LoopbackPeer(parent)
    , m_behaviour(behaviour)
    , m_answer(std::move(answer))
{
    m_flood.setInterval(1);
    connect(&m_flood, &QTimer::timeout, this, &RawPeer::flood);
}

void RawPeer::serve(QTcpSocket *socket, const QByteArray &)
{
    if (m_behaviour == Behaviour::Garbage)
        socket->write(m_answer);
}

void RawPeer::accepted(QTcpSocket *)
{
    if (m_behaviour == Behaviour::Flood && !m_flood.isActive())
        m_flood.start();
}

void RawPeer::flood()
{
    for (QTcpSocket *s : sockets()) {
        if (s->bytesToWrite() > kMaxUnsent)
            continue;
        QByteArray chunk;
        for (int i = 0; i < kFramesPerTick; ++i) {
            // PDO-like frames of other nodes: valid SLCAN, never an answer to a request.
            chunk += "t1"
                + QByteArray::number(0x80 + (m_framesSent % 0x7F), 16).rightJustified(2, '0') + "8"
                + QByteArray::number(m_framesSent, 16).rightJustified(16, '0').right(16) + '\r';
            ++m_framesSent;
        }
        s->write(chunk);
    }
}

HostileRefgoPeer::HostileRefgoPeer(Fault fault, QSet<QString> faulty)
    : m_fault(fault)
    , m_faulty(std::move(faulty))
{ }

QString HostileRefgoPeer::uri() const
{
    return QStringLiteral("refgo://127.0.0.1:%1").arg(serverPort());
}

void HostileRefgoPeer::serve(QTcpSocket *socket, const QByteArray &bytes)
{
    m_buffer += bytes;
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

namespace {

// "OR6083,0" -> "6083,0" (the object as "INDEX,SUB"); empty for other commands.
QByteArray objectOf(const QByteArray &line)
{
    static const QRegularExpression re(QStringLiteral("^O[RW]\\s*([0-9A-Fa-f]+),([0-9A-Fa-f]+)"));
    const auto m = re.match(QString::fromLatin1(line));
    return m.hasMatch() ? (m.captured(1) + u',' + m.captured(2)).toLatin1() : QByteArray();
}

QByteArray healthyAnswer(const QByteArray &line)
{
    if (line.startsWith("OW"))
        return line + "\r\n" + line + ",OK\r\n>";
    if (line.startsWith("OR"))
        return line + "\r\nOR" + objectOf(line) + ",0\r\n>";
    return line + "\r\n>";
}

} // namespace

QByteArray HostileRefgoPeer::answer(const QByteArray &line)
{
    ++m_requests;
    const QByteArray object = objectOf(line);
    const QByteArray good = healthyAnswer(line);
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

AbortingSlcanPeer::AbortingSlcanPeer(quint8 node, quint32 abortCode)
    : m_node(node)
    , m_abortCode(abortCode)
{ }

QString AbortingSlcanPeer::uri() const
{
    return QStringLiteral("canopen+slcan://127.0.0.1:%1?node=%2").arg(serverPort()).arg(m_node);
}

void AbortingSlcanPeer::serve(QTcpSocket *socket, const QByteArray &bytes)
{
    for (const slcan::Message &m : m_decoder.feed(bytes)) {
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

} // namespace db::test
