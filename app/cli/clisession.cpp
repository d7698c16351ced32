#include "clisession.h"

#include "canopen/canopenconnection.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

int exitCodeFor(const Error &error)
{
    switch (error.kind()) {
    case Error::Kind::None:
        return ExitOk;
    case Error::Kind::InvalidArgument:
    case Error::Kind::OutOfRange:
    case Error::Kind::AccessDenied:
        return ExitUsage;
    case Error::Kind::ConnectionRefused:
    case Error::Kind::HostNotFound:
    case Error::Kind::Disconnected:
        return ExitConnection;
    case Error::Kind::Timeout:
        return ExitTimeout;
    case Error::Kind::Malformed:
        return ExitMalformed;
    case Error::Kind::DeviceError:
    case Error::Kind::NotSupported:
        return ExitDeviceError;
    default:
        return ExitFailure;
    }
}

Result<const AddressFormat *> addressFormatFor(const ProtocolRegistry &registry,
                                               const QString &uriText)
{
    const auto uri = registry.parseUri(uriText);
    if (!uri)
        return uri.error();
    const ProtocolInfo *protocol = registry.find(uri->scheme());
    return protocol && protocol->addressFormat ? protocol->addressFormat
                                               : &AddressFormat::canopen();
}

Result<ObjectAddress> parseAddressFor(const ProtocolRegistry &registry, const QString &uriText,
                                      const QString &addressText)
{
    const auto format = addressFormatFor(registry, uriText);
    if (!format)
        return format.error();
    return (*format)->parse(addressText);
}

Session::Session(const ProtocolRegistry &registry, const Options &options)
    : m_registry(registry)
    , m_options(options)
{ }

Session::~Session()
{
    if (!m_connection || m_connection->state() == DeviceConnection::State::Disconnected)
        return;
    QEventLoop loop;
    QObject::connect(m_connection.get(), &DeviceConnection::stateChanged, &loop,
                     [&](DeviceConnection::State s) {
                         if (s == DeviceConnection::State::Disconnected)
                             loop.quit();
                     });
    QTimer::singleShot(1000, &loop, &QEventLoop::quit);
    m_connection->close();
    if (m_connection->state() != DeviceConnection::State::Disconnected)
        loop.exec();
}

Result<void> Session::open(const QString &uriText)
{
    auto plan = m_registry.prepare(uriText, m_options.connectTimeoutMs, m_options.requestTimeoutMs);
    if (!plan)
        return plan.error();
    if (!m_options.sdoMode.isEmpty()) {
        // --sdo is the URI's ?sdo= given on the command line.
        const ProtocolInfo *protocol = m_registry.find(plan->uri.scheme());
        if (!protocol || protocol->key != u"canopen")
            return Error(Error::Kind::InvalidArgument, Tr::tr("--sdo needs a canopen+... URI"));
        if (const auto mode = canopen::CanopenConnection::sdoModeFromText(m_options.sdoMode); !mode)
            return mode.error();
        plan.value().uri.setQueryValue(QStringLiteral("sdo"), m_options.sdoMode);
    }
    if (m_options.ram) {
        // --ram is the URI's ?ram given on the command line.
        const ProtocolInfo *protocol = m_registry.find(plan->uri.scheme());
        if (!protocol || protocol->key != u"vabus")
            return Error(Error::Kind::InvalidArgument, Tr::tr("--ram needs a vabus:// URI"));
        plan.value().uri.setQueryValue(QStringLiteral("ram"), QString());
    }
    auto created = m_registry.create(plan.value());
    if (!created)
        return created.error();
    m_connection = created.value();

    return m_connection->openAndWait(m_options.connectTimeoutMs);
}

const AddressFormat &Session::addressFormat() const
{
    return m_connection ? m_connection->addressFormat() : AddressFormat::canopen();
}

Result<QVariant> Session::read(ObjectAddress address)
{
    return Reply::wait(m_connection->read(address));
}

Result<void> Session::write(ObjectAddress address, const QVariant &raw)
{
    auto result = Reply::wait(m_connection->write(address, raw));
    if (!result)
        return result.error();
    return {};
}

} // namespace db::cli
