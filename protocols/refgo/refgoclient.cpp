#include "refgoclient.h"

#include "refgologging.h"
#include "transport/bytestream.h"

namespace db::refgo {

namespace {

// Spec 3.7 gives no error reply; our simulator answers "ERROR <reason>" and Fullmo's own test
// client treats '?' as a failure (Appendix C).
std::optional<QString> deviceErrorLine(const QStringList &lines)
{
    for (const QString &line : lines) {
        if (line.trimmed().startsWith(QLatin1String("ERROR"), Qt::CaseInsensitive)
            || line.contains(QLatin1Char('?')))
            return line;
    }
    return std::nullopt;
}

QString describeAnswer(const QStringList &lines)
{
    return lines.isEmpty() ? QStringLiteral("(no result)") : lines.join(QLatin1String(" / "));
}

} // namespace

RefgoClient::RefgoClient(ByteStream *stream, QObject *parent)
    : QObject(parent)
    , m_stream(stream)
{
    qRegisterMetaType<db::Error>();
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &RefgoClient::onTimeout);
    connect(m_stream, &ByteStream::received, this, &RefgoClient::onReceived);
    connect(m_stream, &ByteStream::closed, this, &RefgoClient::onClosed);
}

RefgoClient::~RefgoClient()
{
    failAll(Error(Error::Kind::Cancelled, QStringLiteral("RefGo client deleted")));
}

int RefgoClient::pendingCount() const
{
    return int(m_queue.size()) + (m_inFlight ? 1 : 0);
}

Reply *RefgoClient::execute(const QString &rawCommand)
{
    if (rawCommand.contains(QLatin1Char('\r')) || rawCommand.contains(QLatin1Char('\n')))
        return Reply::failed({},
                             Error(Error::Kind::InvalidArgument,
                                   QStringLiteral("a RefGo command is one line; CR and LF "
                                                  "are not allowed")));
    if (rawCommand.trimmed().isEmpty())
        return Reply::failed(
            {}, Error(Error::Kind::InvalidArgument, QStringLiteral("empty RefGo command")));
    for (const QChar c : rawCommand) {
        if (c.unicode() < 0x20 || c.unicode() > 0x7e)
            return Reply::failed({},
                                 Error(Error::Kind::InvalidArgument,
                                       QStringLiteral("RefGo command '%1' contains a "
                                                      "non-printable or non-ASCII character")
                                           .arg(rawCommand)));
    }
    return enqueue(rawCommand,
                   [](const QStringList &lines) -> Result<QVariant> { return QVariant(lines); });
}

Reply *RefgoClient::enqueue(const QString &text, Decoder decode, ObjectAddress address)
{
    if (!m_stream->isOpen())
        return Reply::failed(address,
                             Error(Error::Kind::Disconnected,
                                   QStringLiteral("cannot send '%1': not connected to %2")
                                       .arg(text, m_stream->peerName())));
    auto *reply = new Reply(address);
    m_queue.append(Request { text, std::move(decode), reply });
    sendNext();
    return reply;
}

void RefgoClient::sendNext()
{
    while (!m_inFlight && !m_queue.isEmpty()) {
        Request request = m_queue.takeFirst();
        if (!request.reply)
            continue; // the requester deleted it before it was sent
        const QByteArray bytes = request.text.toLatin1() + '\r';
        if (!m_stream->write(bytes)) {
            request.reply->fail(Error(Error::Kind::Disconnected,
                                      QStringLiteral("cannot send '%1': not connected to %2")
                                          .arg(request.text, m_stream->peerName())));
            continue;
        }
        qCDebug(lcRefgoRaw).noquote() << m_stream->peerName() << "->" << bytes;
        const QString text = request.text;
        m_inFlight = std::move(request);
        m_timer.start(m_timeoutMs);
        Q_EMIT logLine(QStringLiteral("> ") + text);
    }
}

void RefgoClient::onReceived(const QByteArray &bytes)
{
    qCDebug(lcRefgoRaw).noquote() << m_stream->peerName() << "<-" << bytes;
    for (const Result<Answer> &answer : m_framer.feed(bytes)) {
        if (answer.ok()) {
            onAnswer(answer.value());
            continue;
        }
        const Error error = answer.error().prefixed(m_stream->peerName());
        qCWarning(lcRefgo).noquote() << error.toString();
        Q_EMIT logLine(QStringLiteral("! ") + error.message());
        if (m_inFlight)
            complete(error);
    }
}

void RefgoClient::onAnswer(const Answer &answer)
{
    // The drive answers in order (spec 3.1), so a late answer to a timed-out command arrives
    // before the answer to whatever was sent after it.
    const qsizetype late = m_abandoned.indexOf(answer.echo);
    const bool matchesInFlight = m_inFlight && answer.echo == m_inFlight->text;
    if (late == 0 || (late > 0 && !matchesInFlight)) {
        qCWarning(lcRefgo).noquote() << "dropping late answer to" << answer.echo
                                     << "(timed out earlier):" << describeAnswer(answer.lines);
        Q_EMIT logLine(QStringLiteral("! dropped late answer to '%1'").arg(answer.echo));
        m_abandoned.remove(0, late + 1);
        return;
    }
    if (!m_inFlight) {
        qCWarning(lcRefgo).noquote()
            << "dropping unsolicited answer" << answer.echo << describeAnswer(answer.lines);
        Q_EMIT logLine(QStringLiteral("! dropped unsolicited answer '%1'").arg(answer.echo));
        return;
    }
    if (!matchesInFlight) {
        complete(Error(Error::Kind::Malformed,
                       QStringLiteral("answer from %1 does not belong to '%2': echo is '%3'")
                           .arg(m_stream->peerName(), m_inFlight->text, answer.echo)));
        return;
    }
    if (!m_abandoned.isEmpty()) {
        qCDebug(lcRefgo) << "timed-out commands never answered:" << m_abandoned;
        m_abandoned.clear();
    }
    Q_EMIT logLine(QStringLiteral("< ") + describeAnswer(answer.lines));
    if (const auto line = deviceErrorLine(answer.lines)) {
        complete(Error(Error::Kind::DeviceError,
                       QStringLiteral("drive refused '%1': %2").arg(answer.echo, *line)));
        return;
    }
    complete(m_inFlight->decode(answer.lines));
}

void RefgoClient::onTimeout()
{
    if (!m_inFlight)
        return;
    m_abandoned.append(m_inFlight->text);
    if (m_abandoned.size() > kMaxAbandoned)
        m_abandoned.removeFirst();
    complete(Error(Error::Kind::Timeout,
                   QStringLiteral("no answer to '%1' from %2 within %3 ms")
                       .arg(m_inFlight->text, m_stream->peerName())
                       .arg(m_timeoutMs)));
}

void RefgoClient::onClosed(const Error &error)
{
    m_timer.stop();
    m_framer.reset();
    m_abandoned.clear();
    failAll(error.isError()
                ? error
                : Error(Error::Kind::Disconnected,
                        QStringLiteral("connection to %1 closed").arg(m_stream->peerName())));
}

void RefgoClient::complete(const Result<QVariant> &result)
{
    m_timer.stop();
    const Request request = std::move(*m_inFlight);
    m_inFlight.reset();
    if (!result.ok()) {
        qCInfo(lcRefgo).noquote() << result.error().toString();
        Q_EMIT logLine(QStringLiteral("! ") + result.error().message());
    }
    if (request.reply) {
        if (result.ok())
            request.reply->finish(result.value());
        else
            request.reply->fail(result.error());
    }
    sendNext();
}

void RefgoClient::failAll(const Error &error)
{
    m_timer.stop();
    QList<Request> all = std::exchange(m_queue, {});
    if (m_inFlight)
        all.prepend(std::move(*m_inFlight));
    m_inFlight.reset();
    for (const Request &request : all) {
        if (request.reply)
            request.reply->fail(error);
    }
}

} // namespace db::refgo
