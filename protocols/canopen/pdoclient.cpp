#include "pdoclient.h"

#include "sdoabort.h"
#include "sdoclient.h"

#include <QPointer>

#include <QCoreApplication>
#include <QtEndian>
#include <algorithm>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

namespace {

QByteArray le(quint32 value, int size)
{
    QByteArray bytes(4, '\0');
    qToLittleEndian(value, bytes.data());
    return bytes.left(size);
}

// An upload's bytes as an unsigned number of at most `size` bytes (an expedited answer without
// size indication carries 4 bytes for smaller objects).
quint32 unsignedOf(const QByteArray &bytes, int size)
{
    quint32 v = 0;
    for (qsizetype i = qMin<qsizetype>(bytes.size(), size) - 1; i >= 0; --i)
        v = (v << 8) | quint8(bytes.at(i));
    return v;
}

bool missing(const Error &error)
{
    return error.kind() == Error::Kind::DeviceError
        && (error.deviceCode() == abort::NoSuchObject
            || error.deviceCode() == abort::NoSuchSubIndex);
}

} // namespace

PdoClient::PdoClient(SdoClient *sdo, QObject *parent)
    : QObject(parent)
    , m_sdo(sdo)
{ }

void PdoClient::step(Reply *outer, Reply *inner, Then then)
{
    QPointer<Reply> target(outer);
    inner->setParent(this);
    connect(inner, &Reply::finished, this, [inner, target, then] {
        inner->deleteLater();
        if (!target)
            return;
        if (inner->ok())
            then(inner->value().toByteArray());
        else
            then(inner->error().prefixed(inner->address().toString()));
    });
}

// Graph: comm 1 -> comm 2 -> comm 3 (optional) -> comm 5 (optional) -> map 0 -> map 1..n
Reply *PdoClient::read(NodeId node, PdoDirection direction, int number)
{
    auto *outer = new Reply(ObjectAddress(0, 0));
    PdoConfig config;
    config.direction = direction;
    config.number = number;
    if (number < 0 || number >= PdoConfig::kMaxPerDirection) {
        outer->fail(Error(Error::Kind::InvalidArgument,
                          Tr::tr("PDO number %1 out of range").arg(number + 1)));
        return outer;
    }
    const quint16 comm = config.communicationIndex();
    step(outer, m_sdo->upload(node, { comm, 1 }), [=, this](const Result<QByteArray> &cob) mutable {
        if (!cob)
            return void(outer->fail(cob.error()));
        config.cobId = unsignedOf(*cob, 4);
        step(outer, m_sdo->upload(node, { comm, 2 }),
             [=, this](const Result<QByteArray> &type) mutable {
                 if (!type)
                     return void(outer->fail(type.error()));
                 config.transmissionType = quint8(unsignedOf(*type, 1));
                 step(outer, m_sdo->upload(node, { comm, 3 }),
                      [=, this](const Result<QByteArray> &inhibit) mutable {
                          if (!inhibit && !missing(inhibit.error()))
                              return void(outer->fail(inhibit.error()));
                          if (inhibit)
                              config.inhibitTime = quint16(unsignedOf(*inhibit, 2));
                          step(outer, m_sdo->upload(node, { comm, 5 }),
                               [=, this](const Result<QByteArray> &event) mutable {
                                   if (!event && !missing(event.error()))
                                       return void(outer->fail(event.error()));
                                   if (event)
                                       config.eventTimer = quint16(unsignedOf(*event, 2));
                                   readMapping(node, outer, config, -1);
                               });
                      });
             });
    });
    return outer;
}

void PdoClient::readMapping(NodeId node, Reply *outer, PdoConfig config, int count)
{
    const quint16 map = config.mappingIndex();
    const int have = int(config.entries.size());
    if (count < 0) {
        step(outer, m_sdo->upload(node, { map, 0 }), [=, this](const Result<QByteArray> &n) {
            if (!n)
                return void(outer->fail(n.error()));
            readMapping(node, outer, config, qMin<int>(unsignedOf(*n, 1), PdoConfig::kMaxEntries));
        });
        return;
    }
    if (have >= count)
        return void(outer->finish(QVariant::fromValue(config)));
    step(outer, m_sdo->upload(node, { map, quint8(have + 1) }),
         [=, this](const Result<QByteArray> &entry) mutable {
             if (!entry)
                 return void(outer->fail(entry.error()));
             config.entries.append(PdoMappingEntry::fromRaw(unsignedOf(*entry, 4)));
             readMapping(node, outer, config, count);
         });
}

Reply *PdoClient::readAll(NodeId node, const ObjectDictionary &dictionary,
                          std::optional<PdoDirection> only)
{
    auto *outer = new Reply(ObjectAddress(0, 0));
    QList<PdoConfig> todo;
    for (const ObjectDef &def : dictionary.objects()) {
        const quint16 i = def.address.index;
        if (def.address.sub != 1 || i < 0x1400 || (i >= 0x1600 && i < 0x1800) || i >= 0x1A00)
            continue;
        PdoConfig c;
        c.direction = i < 0x1600 ? PdoDirection::Receive : PdoDirection::Transmit;
        c.number = i - (i < 0x1600 ? 0x1400 : 0x1800);
        todo.append(c);
    }
    const bool probing = todo.isEmpty();
    if (probing) {
        PdoConfig rx;
        rx.direction = PdoDirection::Receive;
        PdoConfig tx;
        tx.direction = PdoDirection::Transmit;
        todo = { rx, tx };
    }
    if (only)
        todo.removeIf([&](const PdoConfig &c) { return c.direction != *only; });
    std::sort(todo.begin(), todo.end(), [](const PdoConfig &a, const PdoConfig &b) {
        return a.communicationIndex() < b.communicationIndex();
    });
    readNext(node, outer, {}, todo, probing);
    return outer;
}

void PdoClient::readNext(NodeId node, Reply *outer, QList<PdoConfig> done, QList<PdoConfig> todo,
                         bool probing)
{
    if (todo.isEmpty()) {
        outer->finish(QVariant::fromValue(done));
        return;
    }
    const PdoConfig next = todo.takeFirst();
    Reply *inner = read(node, next.direction, next.number);
    QPointer<Reply> target(outer);
    inner->setParent(this);
    connect(inner, &Reply::finished, this, [=, this]() mutable {
        inner->deleteLater();
        if (!target)
            return;
        if (!inner->ok() && !missing(inner->error()))
            return void(outer->fail(inner->error()));
        if (inner->ok()) {
            done.append(inner->value().value<PdoConfig>());
            if (probing && next.number + 1 < PdoConfig::kMaxPerDirection) {
                PdoConfig following = next;
                ++following.number;
                todo.prepend(following);
            }
        }
        readNext(node, outer, done, todo, probing);
    });
}

QList<PdoClient::Write> PdoClient::configureSequence(const PdoConfig &config)
{
    const quint16 comm = config.communicationIndex();
    const quint16 map = config.mappingIndex();
    QList<Write> writes;
    writes.append({ { comm, 1 }, le(config.cobId | PdoConfig::kInvalidBit, 4) });
    writes.append({ { comm, 2 }, le(config.transmissionType, 1) });
    if (config.inhibitTime)
        writes.append({ { comm, 3 }, le(*config.inhibitTime, 2) });
    if (config.eventTimer)
        writes.append({ { comm, 5 }, le(*config.eventTimer, 2) });
    writes.append({ { map, 0 }, le(0, 1) });
    for (qsizetype i = 0; i < config.entries.size() && i < PdoConfig::kMaxEntries; ++i)
        writes.append({ { map, quint8(i + 1) }, le(config.entries.at(i).toRaw(), 4) });
    writes.append({ { map, 0 }, le(quint32(config.entries.size()), 1) });
    if (config.isEnabled())
        writes.append({ { comm, 1 }, le(config.cobId, 4) });
    return writes;
}

Reply *PdoClient::configure(NodeId node, const PdoConfig &config)
{
    auto *outer = new Reply(ObjectAddress(config.communicationIndex(), 1));
    if (config.entries.size() > PdoConfig::kMaxEntries || config.totalBits() > 64) {
        outer->fail(Error(Error::Kind::InvalidArgument,
                          Tr::tr("%1: %2 bits mapped, a CAN frame carries 64")
                              .arg(config.name())
                              .arg(config.totalBits())));
        return outer;
    }
    runWrites(node, outer, configureSequence(config));
    return outer;
}

void PdoClient::runWrites(NodeId node, Reply *outer, QList<Write> writes)
{
    if (writes.isEmpty()) {
        outer->finish();
        return;
    }
    const Write next = writes.takeFirst();
    Reply *inner = m_sdo->download(node, next.address, next.data, SdoClient::Mode::Auto);
    step(outer, inner, [=, this](const Result<QByteArray> &done) {
        if (!done)
            return void(outer->fail(done.error().prefixed(Tr::tr("configuring PDO, writing"))));
        runWrites(node, outer, writes);
    });
}

} // namespace db::canopen
