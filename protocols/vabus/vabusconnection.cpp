#include "vabusconnection.h"

#include "transport/bytestream.h"

#include <QCoreApplication>

namespace db::vabus {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::vabus)
};

constexpr int kMaxNodeId = 63;

} // namespace

Result<quint8> VabusConnection::sysFromUri(const ConnectionUri &uri)
{
    if (!uri.hasQuery(QStringLiteral("sys")))
        return quint8(0);
    const auto node = uri.queryInt(QStringLiteral("sys"), 0, kMaxNodeId);
    if (!node)
        return node.error();
    return quint8(node.value() == 0 ? 0 : kSlaveSysBase + node.value());
}

Result<void> VabusConnection::checkUri(const ConnectionUri &uri)
{
    if (uri.host().isEmpty())
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("%1 names no host").arg(uri.toString()));
    if (auto sys = sysFromUri(uri); !sys)
        return sys.error();
    return {};
}

VabusConnection::VabusConnection(const ConnectionUri &uri, QObject *parent)
    : StreamConnection(uri, kDefaultPort, parent)
{
    init();
}

VabusConnection::VabusConnection(const ConnectionUri &uri, ByteStream *stream, QObject *parent)
    : StreamConnection(uri, stream, parent)
{
    init();
}

VabusConnection::~VabusConnection()
{
    // The client goes first: its replies fail with Cancelled while the stream still exists.
    delete m_client;
    m_client = nullptr;
}

void VabusConnection::init()
{
    m_client = new VabusClient(stream(), this);
    const auto sys = sysFromUri(uri());
    m_client->setSys(sys ? sys.value() : 0);
    m_ram = uri().hasQuery(QStringLiteral("ram"));
    connect(m_client, &VabusClient::logLine, this, &DeviceConnection::logLine);
    m_blocks = new BlockReader(this);
    setRetryAfterLoss(kPowerUpWindowMs);
    followStream();
}

QString VabusConnection::reconnectingLine() const
{
    return Tr::tr("connecting to %1 again (the inverter may be starting up)")
        .arg(stream()->peerName());
}

std::optional<ObjectAddress> VabusConnection::ramAddress(ObjectAddress address) const
{
    if (address.sub > kMaxReadDataSet)
        return std::nullopt;
    return ObjectAddress(address.index, quint8(address.sub + kRamDataSetOffset));
}

QString VabusConnection::connectedLine() const
{
    return QStringLiteral("connected to %1; the inverter reacts as parameter 388 says 10 s after "
                          "the last exchange once the link stops")
        .arg(stream()->peerName());
}

const ObjectDef *VabusConnection::describe(ObjectAddress address) const
{
    if (const ObjectDef *def = dictionary().find(address))
        return def;
    if (address.sub > kMaxReadDataSet && address.sub <= kMaxWriteDataSet) {
        const ObjectAddress eeprom(address.index, quint8(address.sub - kRamDataSetOffset));
        if (const ObjectDef *def = dictionary().find(eeprom))
            return def;
    }
    return dictionary().find(ObjectAddress(address.index, 0));
}

void VabusConnection::doRead(Reply *reply, const ObjectDef *def)
{
    const ObjectAddress address = reply->address();
    if (!def)
        def = describe(address);
    std::optional<DataType> type;
    if (def)
        type = def->type;
    m_client->setTimeoutMs(requestTimeoutMs());
    // The reply is the request's context: deleted before it is sent, the read is withdrawn.
    m_client->read(address.index, address.sub, type, Completion(reply));
}

void VabusConnection::doWrite(Reply *reply, const QVariant &raw, const ObjectDef *def)
{
    const ObjectAddress address = reply->address();
    if (address.index == kBlockDefinitionParameter || address.index == kBlockWriteParameter) {
        // Another definition would make the block's users decode the wrong parameters, and a
        // block write (18) would write the parameters of their definition.
        if (m_blocks->inUse()) {
            reply->fail(Error(Error::Kind::AccessDenied,
                              QStringLiteral("parameter %1 cannot be written now: the block "
                                             "definition (17) holds the parameters this program "
                                             "is polling (status, scope)")
                                  .arg(address.index)));
            return;
        }
        m_blocks->forgetDefinition();
    }
    QVariant value = raw;
    if (!def) {
        // A RAM data set, or a data set the description lists only as data set 0: checked
        // against that description here, as DeviceConnection::write() does for listed ones.
        def = describe(address);
        if (def) {
            if (!def->writable()) {
                reply->fail(Error(Error::Kind::AccessDenied,
                                  QStringLiteral("parameter %1 %2 is read-only")
                                      .arg(address.index)
                                      .arg(def->name)));
                return;
            }
            auto checked = def->validate(raw, addressFormat());
            if (!checked) {
                reply->fail(checked.error());
                return;
            }
            value = checked.value();
        }
    }
    DataType type = DataType::VisibleString;
    if (def) {
        type = def->type;
    } else if (raw.typeId() != QMetaType::QString) {
        reply->fail(Error(Error::Kind::NotSupported,
                          QStringLiteral("parameter %1 is not in the description, so its size "
                                         "on the wire is unknown; give its type (e.g. --type "
                                         "i16, u16 or i32)")
                              .arg(address.index)));
        return;
    }
    quint8 dataSet = address.sub;
    if (m_ram && dataSet <= kMaxReadDataSet)
        dataSet += kRamDataSetOffset;
    m_client->setTimeoutMs(requestTimeoutMs());
    Reply::forward(m_client->write(address.index, dataSet, type, value), reply, this);
}

} // namespace db::vabus
