#include "requestengine.h"
#include <QCoreApplication>
#include <QMetaMethod>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::transport)
};
} // namespace

namespace db {

RequestEngineBase::RequestEngineBase(ByteStream *stream, Category category, Category rawCategory,
                                     QObject *parent)
    : QObject(parent)
    , m_stream(stream)
    , m_category(category)
    , m_rawCategory(rawCategory)
    , m_timer([this] { onTimeout(); })
{
    qRegisterMetaType<db::Error>();
    m_quiet.setSingleShot(true);
    m_quiet.setInterval(0);
    m_keepAlive.setSingleShot(true);
    connect(&m_quiet, &QTimer::timeout, this, [this] { onQuietOver(); });
    connect(&m_keepAlive, &QTimer::timeout, this, [this] { onKeepAliveDue(); });
    connect(m_stream, &ByteStream::received, this,
            [this](const QByteArray &bytes) { onReceived(bytes); });
    connect(m_stream, &ByteStream::opened, this, [this] { restartKeepAlive(); });
    connect(m_stream, &ByteStream::closed, this, [this](const Error &error) {
        m_quiet.stop();
        m_keepAlive.stop();
        m_timeoutsInRow = 0; // a new link starts a new episode
        onClosed(error);
    });
}

bool RequestEngineBase::writeRaw(const QByteArray &bytes)
{
    if (!m_stream->write(bytes))
        return false;
    qCDebug(m_rawCategory).noquote() << m_stream->peerName() << "->" << bytes;
    return true;
}

bool RequestEngineBase::wantsLogLines() const
{
    if (m_wantsLogLines < 0) {
        static const QMetaMethod signal = QMetaMethod::fromSignal(&RequestEngineBase::logLine);
        m_wantsLogLines = isSignalConnected(signal) ? 1 : 0;
    }
    return m_wantsLogLines > 0;
}

void RequestEngineBase::connectNotify(const QMetaMethod &signal)
{
    if (signal == QMetaMethod::fromSignal(&RequestEngineBase::logLine))
        m_wantsLogLines = 1;
}

void RequestEngineBase::disconnectNotify(const QMetaMethod &signal)
{
    Q_UNUSED(signal) // invalid when every connection of a receiver goes at once
    m_wantsLogLines = -1;
}

void RequestEngineBase::transmitted(const QString &label, int transmission, bool keepAlive)
{
    m_timer.start(m_timeoutMs);
    restartKeepAlive();
    if (keepAlive) {
        qCDebug(m_category).noquote() << "keep-alive" << label << "to" << m_stream->peerName();
        return;
    }
    if (!wantsLogLines())
        return;
    if (transmission == 1)
        Q_EMIT logLine(QStringLiteral("> ") + label);
    else
        Q_EMIT logLine(QStringLiteral("> %1 (transmission %2 of %3)")
                           .arg(label)
                           .arg(transmission)
                           .arg(m_maxTransmissions));
}

void RequestEngineBase::startQuiet()
{
    if (m_quiet.interval() > 0)
        m_quiet.start();
}

void RequestEngineBase::enableKeepAlive(int idleMs)
{
    m_keepAliveIdleMs = qMax(0, idleMs);
    m_keepAlive.stop();
    if (m_keepAliveIdleMs > 0) {
        m_keepAlive.setInterval(m_keepAliveIdleMs);
        restartKeepAlive();
    }
}

void RequestEngineBase::restartKeepAlive()
{
    if (m_keepAliveIdleMs > 0 && m_stream->isOpen())
        m_keepAlive.start();
}

void RequestEngineBase::finish(Completion &done, bool keepAlive, const Result<QVariant> &result)
{
    const bool timedOut = !result.ok() && result.error().kind() == Error::Kind::Timeout;
    if (!result.ok()) {
        const QString what = keepAlive ? QStringLiteral("keep-alive: ") : QString();
        if (timedOut && m_timeoutsInRow > 0)
            qCDebug(m_category).noquote() << what + result.error().toString();
        else
            qCInfo(m_category).noquote() << what + result.error().toString();
        Q_EMIT logLine(QStringLiteral("! ") + what + result.error().message());
    }
    if (timedOut) {
        ++m_timeoutsInRow;
    } else if (result.ok() || result.error().kind() == Error::Kind::DeviceError) {
        if (m_timeoutsInRow > 1)
            qCInfo(m_category).noquote() << QStringLiteral("%1 answers again after %2 timeouts")
                                                .arg(m_stream->peerName())
                                                .arg(m_timeoutsInRow);
        m_timeoutsInRow = 0;
    }
    done.complete(result, m_submitting); // nothing for a keep-alive or a requester gone
}

void RequestEngineBase::logReceivedRaw(const QByteArray &bytes) const
{
    qCDebug(m_rawCategory).noquote() << m_stream->peerName() << "<-" << bytes;
}

void RequestEngineBase::logAnswer(const QString &summary, bool keepAlive)
{
    if (keepAlive)
        qCDebug(m_category).noquote() << "keep-alive answered:" << summary;
    else
        Q_EMIT logLine(QStringLiteral("< ") + summary);
}

void RequestEngineBase::logRetry(const QString &label, const QString &why, int transmission)
{
    qCInfo(m_category).noquote() << why << "- sending" << label << "again, transmission"
                                 << transmission << "of" << m_maxTransmissions;
    Q_EMIT logLine(QStringLiteral("! %1; sending it again").arg(why));
}

void RequestEngineBase::logLate(const QString &label, const QString &identity,
                                const QString &summary)
{
    qCWarning(m_category).noquote()
        << "dropping late answer to" << label << "(timed out earlier):" << identity << summary;
    Q_EMIT logLine(QStringLiteral("! dropped late answer to '%1'").arg(label));
}

void RequestEngineBase::logUnsolicited(const QString &identity, const QString &summary)
{
    qCWarning(m_category).noquote() << "dropping unsolicited answer" << identity << summary;
    Q_EMIT logLine(QStringLiteral("! dropped unsolicited answer '%1'").arg(identity));
}

void RequestEngineBase::logForeign(const QString &label, const QString &reason,
                                   const QString &summary)
{
    qCWarning(m_category).noquote()
        << QStringLiteral("dropping answer that does not belong to %1 (%2): %3")
               .arg(label, reason, summary);
    Q_EMIT logLine(
        QStringLiteral("! dropped answer that does not belong to '%1': %2").arg(label, reason));
}

void RequestEngineBase::logForgotten(const QStringList &labels) const
{
    qCDebug(m_category) << "timed-out requests never answered:" << labels;
}

Error RequestEngineBase::framingError(const Error &error)
{
    const Error named = error.prefixed(m_stream->peerName());
    qCWarning(m_category).noquote() << named.toString();
    Q_EMIT logLine(QStringLiteral("! ") + named.message());
    return named;
}

Error RequestEngineBase::notConnected(const QString &label) const
{
    return Error(Error::Kind::Disconnected,
                 Tr::tr("cannot send '%1': not connected to %2").arg(label, m_stream->peerName()));
}

Error RequestEngineBase::timedOut(const QString &label, int transmissions) const
{
    QString message = Tr::tr("no answer to '%1' from %2 within %3 ms")
                          .arg(label, m_stream->peerName())
                          .arg(m_timeoutMs);
    if (transmissions > 1)
        message += Tr::tr(" (sent %1 times)").arg(transmissions);
    return Error(Error::Kind::Timeout, message);
}

Error RequestEngineBase::foreign(const QString &label, const QString &reason) const
{
    return Error(Error::Kind::Malformed,
                 Tr::tr("answer from %1 does not belong to '%2': %3")
                     .arg(m_stream->peerName(), label, reason));
}

Error RequestEngineBase::closedError(const Error &error) const
{
    return error.isError() ? error
                           : Error(Error::Kind::Disconnected,
                                   Tr::tr("connection to %1 closed").arg(m_stream->peerName()));
}

} // namespace db
