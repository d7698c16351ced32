#include "connectionuri.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QUrl>
#include <QUrlQuery>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

Result<ConnectionUri> ConnectionUri::parse(const QString &text)
{
    const QString trimmed = text.trimmed();
    static const QRegularExpression schemeRe(QStringLiteral("^([a-z][a-z0-9+.-]*)://(.*)$"),
                                             QRegularExpression::CaseInsensitiveOption);
    const auto m = schemeRe.match(trimmed);
    if (!m.hasMatch()) {
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("'%1' is not a connection URI; write e.g. "
                            "refgo://192.168.2.150 or canopen+slcan://HOST?node=50")
                         .arg(text));
    }
    const QUrl url(trimmed, QUrl::StrictMode);
    if (!url.isValid()) {
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("'%1' is not a valid URI (%2)").arg(text, url.errorString()));
    }
    if (url.host().isEmpty()) {
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("'%1' has no valid host or interface").arg(text));
    }
    if (!url.path().isEmpty() && url.path() != QLatin1String("/")) {
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("'%1': unexpected path '%2'").arg(text, url.path()));
    }
    ConnectionUri uri;
    uri.m_scheme = url.scheme().toLower();
    uri.m_host = url.host();
    uri.m_port = url.port(-1);
    const QUrlQuery query(url);
    for (const auto &item : query.queryItems(QUrl::FullyDecoded))
        uri.m_query.insert(item.first.toLower(), item.second);
    return uri;
}

Result<int> ConnectionUri::queryInt(const QString &key, int min, int max) const
{
    const QString text = m_query.value(key);
    bool ok = false;
    const int value = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
        ? text.mid(2).toInt(&ok, 16)
        : text.toInt(&ok, 10);
    if (!ok || value < min || value > max) {
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1=%2 in %3: expected a number from %4 to %5")
                         .arg(key, text.isEmpty() ? QStringLiteral("(missing)") : text, toString())
                         .arg(min)
                         .arg(max));
    }
    return value;
}

QString ConnectionUri::toString() const
{
    QString s = m_scheme + QStringLiteral("://") + m_host;
    if (m_port >= 0)
        s += QLatin1Char(':') + QString::number(m_port);
    if (!m_query.isEmpty()) {
        QStringList parts;
        for (auto it = m_query.cbegin(); it != m_query.cend(); ++it)
            parts.append(it.key() + QLatin1Char('=') + it.value());
        s += QLatin1Char('?') + parts.join(QLatin1Char('&'));
    }
    return s;
}

} // namespace db
