// Every request/response client against the same failure modes of its peer: silence, garbage,
// a partial answer, an answer for another request, endless data without a delimiter, a 10 MB
// line, an answer byte by byte, a reset in the middle of an answer, and an answer that comes too
// late. For each: a clear error (or the right value) within the client's time budget, memory
// that stays bounded, and a late answer that is never taken for the next request's.
//
// The clients are the RefGo connection, CANopen SDO over SLCAN over TCP, and VABus/TCP, made
// from URIs as the programs make them; the peer is one scripted TCP server on loopback.
#include "common/protocols.h"
#include "core/deviceconnection.h"
#include "peers.h"
#include "transport/slcancodec.h"
#include "vabus/vabuscodec.h"
#include "vabus/vabusframer.h"
#include "wait.h"

#include <QElapsedTimer>
#include <QFile>
#include <QPointer>
#include <QRegularExpression>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

using namespace db;

namespace {

constexpr int kTimeoutMs = 300;
constexpr qint64 kValue = 42; // every healthy read answers this
constexpr qint64 kLateValue = 1234; // a late answer carries this
constexpr qint64 kOtherValue = 7; // an answer for another request carries this
constexpr quint8 kNode = 5;

enum class Protocol { Refgo, Slcan, Vabus };
enum class Mode {
    Good,
    Silence,
    Garbage,
    Partial,
    OtherRequest,
    Endless,
    HugeLine,
    ByteByByte,
    ResetMidAnswer,
    Slow,
};

QString protocolName(Protocol p)
{
    switch (p) {
    case Protocol::Refgo:
        return QStringLiteral("refgo");
    case Protocol::Slcan:
        return QStringLiteral("sdo");
    case Protocol::Vabus:
        return QStringLiteral("vabus");
    }
    return {};
}

QString modeName(Mode m)
{
    static const char *const names[] = { "good",    "silence",  "garbage",  "partial", "other",
                                         "endless", "hugeline", "bytewise", "reset",   "slow" };
    return QString::fromLatin1(names[int(m)]);
}

qint64 residentKb()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return 0;
    const auto m = QRegularExpression(QStringLiteral("VmRSS:\\s+(\\d+) kB"))
                       .match(QString::fromLatin1(status.readAll()));
    return m.hasMatch() ? m.captured(1).toLongLong() : 0;
}

// One device of the given protocol on loopback, answering every read with kValue until armed
// with another mode. SLCAN adapter commands are always acknowledged.
class FaultPeer : public test::LoopbackPeer
{
public:
    explicit FaultPeer(Protocol protocol)
        : m_protocol(protocol)
    {
        m_pump.setInterval(1);
        connect(&m_pump, &QTimer::timeout, this, &FaultPeer::pump);
    }

    QString uri() const
    {
        switch (m_protocol) {
        case Protocol::Refgo:
            return QStringLiteral("refgo://127.0.0.1:%1").arg(port());
        case Protocol::Slcan:
            return QStringLiteral("canopen+slcan://127.0.0.1:%1?node=%2").arg(port()).arg(kNode);
        case Protocol::Vabus:
            return QStringLiteral("vabus://127.0.0.1:%1").arg(port());
        }
        return {};
    }
    // The address the test reads (a 16-bit status word on every family).
    ObjectAddress address() const
    {
        return m_protocol == Protocol::Vabus ? ObjectAddress { 411, 0 }
                                             : ObjectAddress { 0x6041, 0 };
    }

    void arm(Mode mode) { m_mode = mode; }
    int requests() const { return m_requests; }

protected:
    void serve(QTcpSocket *socket, const QByteArray &bytes) override
    {
        m_buffer += bytes;
        for (const Request &r : takeRequests(socket))
            respond(socket, r);
    }

private:
    struct Request
    {
        QByteArray good; // the healthy answer
        QByteArray late; // the same answer with kLateValue
        QByteArray other; // an answer for another request
    };

    // Whole requests out of m_buffer, each with its answers; adapter commands answered here.
    QList<Request> takeRequests(QTcpSocket *socket)
    {
        QList<Request> out;
        switch (m_protocol) {
        case Protocol::Refgo: {
            m_buffer.replace('\n', QByteArray());
            qsizetype cr;
            while ((cr = m_buffer.indexOf('\r')) >= 0) {
                const QByteArray line = m_buffer.left(cr);
                m_buffer.remove(0, cr + 1);
                if (line.isEmpty())
                    continue;
                const auto m =
                    QRegularExpression(QStringLiteral("^OR\\s*([0-9A-Fa-f]+),([0-9A-Fa-f]+)"))
                        .match(QString::fromLatin1(line));
                if (!m.hasMatch()) {
                    socket->write(line + "\r\n" + line + ",OK\r\n>");
                    continue;
                }
                const QByteArray object = (m.captured(1) + u',' + m.captured(2)).toLatin1();
                const auto answer = [&](const QByteArray &obj, qint64 v) {
                    return line + "\r\nOR" + obj + ',' + QByteArray::number(v) + "\r\n>";
                };
                out.append({ answer(object, kValue), answer(object, kLateValue),
                             answer(object == "6083,0" ? "6084,0" : "6083,0", kOtherValue) });
            }
            break;
        }
        case Protocol::Slcan: {
            qsizetype cr;
            while ((cr = m_buffer.indexOf('\r')) >= 0) {
                const slcan::Message msg = slcan::parseLine(m_buffer.left(cr));
                m_buffer.remove(0, cr + 1);
                if (msg.kind == slcan::Message::Kind::Command) {
                    socket->write(QByteArray(1, slcan::kCr));
                    continue;
                }
                if (msg.kind != slcan::Message::Kind::Frame || msg.frame.frameId() != 0x600u + kNode
                    || msg.frame.payload().size() != 8)
                    continue;
                const QByteArray rq = msg.frame.payload();
                const auto frame = [&](quint8 cs, quint16 index, quint8 sub, qint64 v) {
                    QByteArray p(8, '\0');
                    p[0] = char(cs);
                    p[1] = char(index & 0xFF);
                    p[2] = char(index >> 8);
                    p[3] = char(sub);
                    for (int i = 0; i < 4; ++i)
                        p[4 + i] = char((v >> (8 * i)) & 0xFF);
                    return slcan::encodeFrame(QCanBusFrame(0x580u + kNode, p));
                };
                const quint16 index = quint16(quint8(rq[1]) | (quint8(rq[2]) << 8));
                const quint8 sub = quint8(rq[3]);
                if ((quint8(rq[0]) & 0xE0) != 0x40) { // not an upload: acknowledge a download
                    socket->write(frame(0x60, index, sub, 0));
                    continue;
                }
                // Expedited upload, 2 bytes (e = 1, s = 1, n = 2): 0x4B.
                out.append({ frame(0x4B, index, sub, kValue), frame(0x4B, index, sub, kLateValue),
                             frame(0x4B, index == 0x6083 ? 0x6084 : 0x6083, sub, kOtherValue) });
            }
            break;
        }
        case Protocol::Vabus: {
            for (const auto &f : m_framer.feed(m_buffer)) {
                if (!f || f.value().kind != vabus::Frame::Kind::Telegram)
                    continue;
                const vabus::Telegram rq = f.value().telegram;
                const auto answer = [&](quint16 parameter, qint64 v) {
                    vabus::Telegram t = rq;
                    t.parameter = parameter;
                    if (!rq.write) {
                        t.data = QByteArray(2, '\0');
                        t.data[0] = char(v & 0xFF);
                        t.data[1] = char((v >> 8) & 0xFF);
                    }
                    return vabus::encode(t).value();
                };
                if (rq.write) {
                    socket->write(answer(rq.parameter, 0));
                    continue;
                }
                out.append({ answer(rq.parameter, kValue), answer(rq.parameter, kLateValue),
                             answer(rq.parameter == 411 ? 412 : 411, kOtherValue) });
            }
            m_buffer.clear();
            break;
        }
        }
        return out;
    }

    QByteArray filler(qsizetype n) const
    {
        // Bytes that never complete an answer: no CR for the text protocols, header bits set
        // for VABus.
        return QByteArray(n, m_protocol == Protocol::Vabus ? char(0xFF) : 'A');
    }

    void respond(QTcpSocket *socket, const Request &r)
    {
        ++m_requests;
        switch (m_mode) {
        case Mode::Good:
            socket->write(r.good);
            break;
        case Mode::Silence:
            break;
        case Mode::Garbage:
            socket->write(m_protocol == Protocol::Vabus ? QByteArray("\xfe\xff\x01\x02\x03", 5)
                                                        : QByteArray("zq!#~\r\n"));
            break;
        case Mode::Partial:
            socket->write(r.good.left(r.good.size() / 2));
            break;
        case Mode::OtherRequest:
            socket->write(r.other);
            break;
        case Mode::Endless:
            m_socket = socket;
            m_endlessLeft = 256LL * 1024 * 1024;
            if (m_protocol == Protocol::Slcan)
                socket->write("t585");
            m_pump.start();
            break;
        case Mode::HugeLine: {
            const QByteArray line = filler(10 * 1024 * 1024);
            m_socket = socket;
            m_queue = m_protocol == Protocol::Refgo ? line + "\r\n>"
                : m_protocol == Protocol::Slcan     ? "t585" + line + "\r"
                                                    : line + r.good;
            m_pump.start();
            break;
        }
        case Mode::ByteByByte:
            // One byte per event-loop pass, each in its own segment: well within the timeout
            // even on a loaded machine, and never two bytes in one read.
            socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
            m_socket = socket;
            m_queue = r.good;
            m_bytewise = true;
            m_pump.start(0);
            break;
        case Mode::ResetMidAnswer:
            socket->write(r.good.left(r.good.size() / 2));
            socket->flush();
            socket->abort();
            break;
        case Mode::Slow:
            QTimer::singleShot(8 * kTimeoutMs, socket,
                               [socket, late = r.late] { socket->write(late); });
            break;
        }
    }

    // Feeds m_queue (bytewise or in chunks) and the endless stream without flooding the
    // socket's own buffer: the peer must not be what grows.
    void pump()
    {
        if (!m_socket || m_socket->state() != QAbstractSocket::ConnectedState) {
            m_pump.stop();
            return;
        }
        if (m_socket->bytesToWrite() > 256 * 1024)
            return;
        if (!m_queue.isEmpty()) {
            const qsizetype n = m_bytewise ? 1 : qMin<qsizetype>(m_queue.size(), 256 * 1024);
            m_socket->write(m_queue.left(n));
            if (m_bytewise)
                m_socket->flush();
            m_queue.remove(0, n);
            return;
        }
        if (m_endlessLeft > 0) {
            const qint64 n = qMin<qint64>(m_endlessLeft, 256 * 1024);
            m_socket->write(filler(n));
            m_endlessLeft -= n;
            return;
        }
        m_bytewise = false;
        m_pump.stop();
        m_pump.setInterval(1);
    }

    Protocol m_protocol;
    Mode m_mode = Mode::Good;
    QByteArray m_buffer;
    vabus::Framer m_framer;
    int m_requests = 0;
    QTimer m_pump;
    QPointer<QTcpSocket> m_socket;
    QByteArray m_queue;
    bool m_bytewise = false;
    qint64 m_endlessLeft = 0;
};

struct Outcome
{
    bool finished = false;
    Error error;
    QVariant value;
    qint64 ms = 0;
};

Outcome readOnce(DeviceConnection &c, ObjectAddress address, int limitMs)
{
    QElapsedTimer t;
    t.start();
    Reply *reply = c.read(address);
    Outcome o;
    o.finished = QTest::qWaitFor([reply] { return reply->isFinished(); }, limitMs);
    o.ms = t.elapsed();
    if (o.finished) {
        o.error = reply->error();
        o.value = reply->value();
    }
    delete reply;
    return o;
}

} // namespace

Q_DECLARE_METATYPE(Protocol)
Q_DECLARE_METATYPE(Mode)

class TestClientFaults : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void faults_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<Mode>("mode");
        for (Protocol p : { Protocol::Refgo, Protocol::Slcan, Protocol::Vabus }) {
            for (int m = 0; m <= int(Mode::Slow); ++m)
                QTest::addRow("%s-%s", qPrintable(protocolName(p)), qPrintable(modeName(Mode(m))))
                    << p << Mode(m);
        }
    }

    void faults()
    {
        QFETCH(Protocol, protocol);
        QFETCH(Mode, mode);
        FaultPeer peer(protocol);
        QVERIFY(peer.isListening());
        auto made = app::protocolRegistry().create(peer.uri());
        QVERIFY2(made, qPrintable(made ? QString() : made.error().toString()));
        std::shared_ptr<DeviceConnection> c = made.value();
        c->setRequestTimeoutMs(kTimeoutMs);
        c->open();
        QTRY_VERIFY_WITH_TIMEOUT(c->isConnected(), 5000);

        // Healthy first: the baseline every mode is compared with.
        Outcome first = readOnce(*c, peer.address(), 5000);
        QVERIFY(first.finished);
        QVERIFY2(!first.error.isError(), qPrintable(first.error.toString()));
        QCOMPARE(first.value.toLongLong(), kValue);

        const qint64 before = residentKb();
        peer.arm(mode);
        // At most three transmissions (VABus), each waiting the timeout, plus slack for a loaded
        // machine. Nothing may take longer, whatever the peer does.
        // Byte by byte takes one event-loop pass per byte of each side: on a loaded machine that
        // can come near the short timeout the other modes use, so this one gets a longer one.
        const int timeoutMs = mode == Mode::ByteByByte ? 5 * kTimeoutMs : kTimeoutMs;
        c->setRequestTimeoutMs(timeoutMs);
        const int budgetMs = 3 * timeoutMs + 1500;
        const Outcome o = readOnce(*c, peer.address(), budgetMs + 5000);
        QVERIFY2(o.finished, "the read never finished");
        QVERIFY2(o.ms <= budgetMs,
                 qPrintable(QStringLiteral("took %1 ms, budget %2 ms").arg(o.ms).arg(budgetMs)));
        const qint64 grownKb = residentKb() - before;
        qInfo("%s: %s after %lld ms, resident memory %+lld kB", qPrintable(modeName(mode)),
              o.error.isError() ? qPrintable(o.error.toString())
                                : qPrintable(QStringLiteral("value %1").arg(o.value.toString())),
              o.ms, grownKb);

        switch (mode) {
        case Mode::Good:
        case Mode::ByteByByte:
            QVERIFY2(!o.error.isError(), qPrintable(o.error.toString()));
            QCOMPARE(o.value.toLongLong(), kValue);
            break;
        case Mode::HugeLine:
            // A clear error, or (VABus, where the garbage is dropped before the answer) the value.
            if (!o.error.isError())
                QCOMPARE(o.value.toLongLong(), kValue);
            break;
        default:
            QVERIFY2(o.error.isError(), qPrintable(o.value.toString()));
            break;
        }
        if (o.error.isError())
            QVERIFY2(!o.error.message().isEmpty(), "an error without a cause");
        if (mode == Mode::Silence || mode == Mode::Partial || mode == Mode::Slow)
            QCOMPARE(o.error.kind(), Error::Kind::Timeout);
        if (mode == Mode::ResetMidAnswer)
            QVERIFY2(o.error.kind() == Error::Kind::Disconnected
                         || o.error.kind() == Error::Kind::Timeout,
                     qPrintable(o.error.toString()));
        // The 10 MB line and the endless stream are dropped as they come, not kept.
        QVERIFY2(grownKb < 48 * 1024, qPrintable(QStringLiteral("grew by %1 kB").arg(grownKb)));

        // A late answer is never taken for the next request: after it arrived, a healthy read
        // gets the healthy value.
        if (mode == Mode::Slow) {
            QTest::qWait(8 * kTimeoutMs - int(o.ms) + 200);
            peer.arm(Mode::Good);
            const Outcome next = readOnce(*c, peer.address(), 5000);
            QVERIFY2(!next.error.isError(), qPrintable(next.error.toString()));
            QCOMPARE(next.value.toLongLong(), kValue);
        }
    }
};

QTEST_GUILESS_MAIN(TestClientFaults)
#include "tst_clientfaults.moc"
