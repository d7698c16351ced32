#include "refgoclient.h"

#include "refgologging.h"
#include <QCoreApplication>
#include <QMetaMethod>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::refgo)
};
} // namespace

namespace db::refgo {

namespace {

// Spec 3.7 gives no error reply; our simulator answers "ERROR <reason>" and Fullmo's own test
// client treats '?' as a failure (Appendix C).
std::optional<QString> deviceErrorLine(const QStringList &lines)
{
    for (const QString &line : lines) {
        if (QStringView(line).trimmed().startsWith(QLatin1String("ERROR"), Qt::CaseInsensitive)
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
    , m_engine(stream, &lcRefgo, &lcRefgoRaw, this)
{
    // The drive answers in order (spec 3.1): an answer that arrives while a command is in
    // flight and is no late one belongs to that command, so a wrong echo breaks the exchange.
    m_engine.setForeignAnswerFails(true);
    m_engine.setTimeoutMs(kDefaultTimeoutMs);
    m_engine.setLateGraceMs(kLateGraceMs);
}

RefgoClient::~RefgoClient()
{
    m_engine.failAll(Error(Error::Kind::Cancelled, Tr::tr("RefGo client deleted")));
}

Reply *RefgoClient::execute(const QString &rawCommand)
{
    if (rawCommand.contains(QLatin1Char('\r')) || rawCommand.contains(QLatin1Char('\n')))
        return Reply::failed({},
                             Error(Error::Kind::InvalidArgument,
                                   Tr::tr("a RefGo command is one line; CR and LF "
                                          "are not allowed")));
    if (rawCommand.trimmed().isEmpty())
        return Reply::failed({},
                             Error(Error::Kind::InvalidArgument, Tr::tr("empty RefGo command")));
    for (const QChar c : rawCommand) {
        if (c.unicode() < 0x20 || c.unicode() > 0x7e)
            return Reply::failed({},
                                 Error(Error::Kind::InvalidArgument,
                                       Tr::tr("RefGo command '%1' contains a "
                                              "non-printable or non-ASCII character")
                                           .arg(rawCommand)));
    }
    return enqueue(rawCommand, [](const QString &, const QStringList &lines) -> Result<QVariant> {
        return QVariant(lines);
    });
}

QByteArray RefgoClient::line(const QString &text)
{
    // The line as sent, CR included, in one allocation (this runs for every request).
    QByteArray bytes(text.size() + 1, '\r');
    char *out = bytes.data();
    for (const QChar c : text)
        *out++ = c.unicode() < 0x100 ? char(c.unicode()) : '?';
    return bytes;
}

Reply *RefgoClient::enqueue(const QString &text, Decoder decode, ObjectAddress address)
{
    auto *reply = new Reply(address);
    enqueue(text, std::move(decode), Completion(reply));
    return reply;
}

void RefgoClient::enqueue(const QString &text, Decoder decode, Completion done)
{
    m_engine.submit(line(text), text, Protocol::Matcher { text, std::move(decode) },
                    std::move(done));
}

Verdict RefgoClient::Protocol::Matcher::operator()(const Answer &answer) const
{
    if (answer.echo != text)
        return Verdict::notMine(QStringLiteral("echo is '%1'").arg(answer.echo));
    if (const auto line = deviceErrorLine(answer.lines))
        return Verdict::mine(Error(Error::Kind::DeviceError,
                                   Tr::tr("drive refused '%1': %2").arg(answer.echo, *line)));
    return Verdict::mine(decode(text, answer.lines));
}

QString RefgoClient::Protocol::summary(const Answer &answer)
{
    return describeAnswer(answer.lines);
}

void RefgoClient::connectNotify(const QMetaMethod &signal)
{
    if (!m_forwardingLog && signal == QMetaMethod::fromSignal(&RefgoClient::logLine)) {
        m_forwardingLog = true;
        connect(&m_engine, &RequestEngineBase::logLine, this, &RefgoClient::logLine);
    }
}

} // namespace db::refgo
