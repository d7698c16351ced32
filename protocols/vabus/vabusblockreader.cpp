#include "vabusblockreader.h"

#include "core/reply.h"
#include "vabusconnection.h"

namespace db::vabus {

namespace {

constexpr int kGroupChars = 5;

int answerChars(const BlockItem &item)
{
    return datatype::byteSize(item.type) * 2;
}

} // namespace

BlockReader::BlockReader(VabusConnection *connection)
    : GroupReader(connection)
    , m_connection(connection)
{
    connect(connection, &DeviceConnection::stateChanged, this, &BlockReader::onConnectionState);
}

void BlockReader::onConnectionState()
{
    // A new TCP connection may lead to a reset inverter: the definition is volatile there.
    m_written.reset();
    m_failures = 0;
    m_usable = true;
}

qsizetype BlockReader::indexOf(const QObject *user) const
{
    for (qsizetype i = 0; i < m_users.size(); ++i) {
        if (m_users.at(i).user == user)
            return i;
    }
    return -1;
}

bool BlockReader::inUse() const
{
    for (const User &u : m_users) {
        if (!u.held.isEmpty())
            return true;
    }
    return false;
}

QList<ObjectAddress> BlockReader::join(const QObject *user, const QList<ObjectAddress> &objects)
{
    qsizetype at = indexOf(user);
    if (at < 0) {
        User u;
        u.user = user;
        u.destroyed = connect(user, &QObject::destroyed, this, [this, user] { leave(user); });
        m_users.append(u);
        at = m_users.size() - 1;
    }
    m_users[at].held.clear();
    rebuild(); // the block without this user's objects

    int definition = int(m_items.size()) * kGroupChars;
    int answer = 0;
    for (const BlockItem &item : std::as_const(m_items))
        answer += answerChars(item);
    QList<ObjectAddress> held;
    for (ObjectAddress address : objects) {
        if (held.contains(address))
            continue;
        bool inBlock = false;
        for (const BlockItem &item : std::as_const(m_items))
            inBlock = inBlock || item.address == address;
        if (!inBlock) {
            const ObjectDef *def = m_connection->describe(address);
            if (!def)
                continue;
            const BlockItem item { address, def->type };
            if (!fitsBlock(item) || definition + kGroupChars > kMaxBlockChars
                || answer + answerChars(item) > kMaxBlockChars)
                continue;
            definition += kGroupChars;
            answer += answerChars(item);
            m_items.append(item);
        }
        held.append(address);
    }
    m_users[at].held = held;
    rebuild();
    return held;
}

void BlockReader::leave(const QObject *user)
{
    const qsizetype at = indexOf(user);
    if (at < 0)
        return;
    disconnect(m_users.at(at).destroyed);
    m_users.removeAt(at);
    rebuild();
}

void BlockReader::rebuild()
{
    // The union in the order the users joined; a shared object keeps its first place.
    QList<BlockItem> items;
    for (const User &u : std::as_const(m_users)) {
        for (ObjectAddress address : u.held) {
            bool known = false;
            for (const BlockItem &item : std::as_const(items))
                known = known || item.address == address;
            if (known)
                continue;
            if (const ObjectDef *def = m_connection->describe(address))
                items.append({ address, def->type });
        }
    }
    m_items = items;
}

QList<ObjectAddress> BlockReader::heldFor(const QObject *user) const
{
    const qsizetype at = indexOf(user);
    return m_usable && at >= 0 ? m_users.at(at).held : QList<ObjectAddress>();
}

Reply *BlockReader::read(const QObject *user)
{
    const QList<ObjectAddress> held = heldFor(user);
    if (held.isEmpty() || m_items.isEmpty())
        return nullptr;
    if (!m_connection->isConnected())
        return Reply::failed(
            ObjectAddress(kBlockReadParameter, 0),
            Error(Error::Kind::Disconnected, QStringLiteral("block read: not connected")));
    VabusClient *client = m_connection->client();
    client->setTimeoutMs(m_connection->requestTimeoutMs());

    const auto text = blockDefinition(m_items);
    if (!text) // cannot happen: join() keeps the block within its limits
        return Reply::failed(ObjectAddress(kBlockReadParameter, 0), text.error());
    if (!m_written || m_written->text != text.value()) {
        auto definition = std::make_shared<Definition>();
        definition->text = text.value();
        definition->items = m_items;
        m_written = definition;
        ++m_definitions;
        // Data set 0 on purpose: 17 is volatile (lost at reset), never an EEPROM write.
        Reply *write = client->writeData(kBlockDefinitionParameter, 0, definition->text,
                                         ObjectAddress(kBlockDefinitionParameter, 0));
        write->setParent(this);
        connect(write, &Reply::finished, this, [this, write, definition] {
            write->deleteLater();
            definition->done = true;
            if (write->ok()) {
                m_failures = 0;
                return;
            }
            definition->error = write->error().prefixed(QStringLiteral("block definition (17)"));
            if (m_written == definition)
                m_written.reset();
            if (++m_failures >= kMaxFailures)
                m_usable = false;
        });
    }
    const std::shared_ptr<Definition> definition = m_written;

    auto *outer = new Reply(ObjectAddress(kBlockReadParameter, 0));
    QPointer<Reply> guard(outer);
    Reply *inner = client->read(kBlockReadParameter, 0, DataType::VisibleString,
                                ObjectAddress(kBlockReadParameter, 0));
    inner->setParent(this);
    connect(inner, &Reply::finished, this, [this, inner, guard, definition, held] {
        inner->deleteLater();
        // The definition was written before this read (one telegram at a time, in order).
        Result<QList<QVariant>> values = definition->error.isError()
            ? Result<QList<QVariant>>(definition->error)
            : inner->ok() ? decodeBlock(inner->value().toString().toLatin1(), definition->items)
                          : Result<QList<QVariant>>(inner->error());
        if (!values && !definition->error.isError() && m_written == definition)
            m_written.reset(); // e.g. a reset inverter lost the definition: write it again
        if (!guard)
            return;
        if (!values) {
            guard->fail(values.error());
            return;
        }
        QVariantList mine;
        for (ObjectAddress address : held) {
            QVariant value;
            for (qsizetype i = 0; i < definition->items.size(); ++i) {
                if (definition->items.at(i).address == address)
                    value = values.value().at(i);
            }
            mine.append(value);
        }
        guard->finish(mine);
    });
    return outer;
}

} // namespace db::vabus
