#include "canbusfactory.h"

#include "transport/qtcanbus.h"

#include "transport/slcanbus.h"
#include "transport/tcpstream.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

QString CanBusFactory::transportOf(const ConnectionUri &uri)
{
    const QString prefix = QStringLiteral("canopen+");
    if (!uri.scheme().startsWith(prefix))
        return {};
    return uri.scheme().mid(prefix.size());
}

Result<int> CanBusFactory::bitrateOf(const ConnectionUri &uri)
{
    if (!uri.hasQuery(QStringLiteral("bitrate")))
        return 0;
    return uri.queryInt(QStringLiteral("bitrate"), 1000, 8000000);
}

Result<void> CanBusFactory::checkInterface(const ConnectionUri &uri)
{
    const QString transport = transportOf(uri);
    if (transport.isEmpty() || transport == u"slcan")
        return {};
    return QtCanBus::checkInterface(transport, uri.host());
}

Result<CanBus *> CanBusFactory::makeBus(const ConnectionUri &uri, QObject *parent)
{
    const QString transport = transportOf(uri);
    if (transport.isEmpty())
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1 is not a CANopen URI (canopen+socketcan://, "
                            "canopen+virtualcan://, canopen+slcan://)")
                         .arg(uri.toString()));
    if (uri.host().isEmpty())
        return Error(
            Error::Kind::InvalidArgument,
            Tr::tr("%1 names no %2")
                .arg(uri.toString(),
                     transport == u"slcan" ? QStringLiteral("host") : QStringLiteral("interface")));
    const auto b = bitrateOf(uri);
    if (!b)
        return b.error();
    const int bitrate = *b;
    if (transport == u"slcan") {
        auto *stream = new TcpStream(uri.host(), quint16(uri.portOr(kDefaultSlcanPort)));
        return static_cast<CanBus *>(
            new SlcanBus(stream, bitrate > 0 ? bitrate : kDefaultSlcanBitrate, parent));
    }
    return static_cast<CanBus *>(new QtCanBus(transport, uri.host(), bitrate, parent));
}

} // namespace db::canopen
