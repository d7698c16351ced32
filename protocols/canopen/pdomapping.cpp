#include "pdomapping.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

PdoMappingEntry PdoMappingEntry::fromRaw(quint32 raw)
{
    return { ObjectAddress(quint16(raw >> 16), quint8(raw >> 8)), quint8(raw & 0xFF) };
}

quint32 PdoMappingEntry::toRaw() const
{
    return (quint32(address.index) << 16) | (quint32(address.sub) << 8) | bits;
}

quint16 PdoConfig::communicationIndex() const
{
    return quint16((direction == PdoDirection::Receive ? 0x1400 : 0x1800) + number);
}

quint16 PdoConfig::mappingIndex() const
{
    return quint16((direction == PdoDirection::Receive ? 0x1600 : 0x1A00) + number);
}

int PdoConfig::totalBits() const
{
    int bits = 0;
    for (const PdoMappingEntry &e : entries)
        bits += e.bits;
    return bits;
}

QString PdoConfig::name() const
{
    return QStringLiteral("%1%2")
        .arg(direction == PdoDirection::Receive ? QLatin1String("RPDO") : QLatin1String("TPDO"))
        .arg(number + 1);
}

QString PdoConfig::toString() const
{
    QString text = QStringLiteral("%1 cob 0x%2 %3 type 0x%4")
                       .arg(name())
                       .arg(canId(), 3, 16, QLatin1Char('0'))
                       .arg(isEnabled() ? QLatin1String("enabled") : QLatin1String("disabled"))
                       .arg(transmissionType, 2, 16, QLatin1Char('0'));
    if (inhibitTime)
        text += QStringLiteral(" inhibit %1").arg(*inhibitTime);
    if (eventTimer)
        text += QStringLiteral(" event %1 ms").arg(*eventTimer);
    text += QLatin1Char(':');
    if (entries.isEmpty())
        text += QLatin1String(" (nothing mapped)");
    for (const PdoMappingEntry &e : entries)
        text += QStringLiteral(" %1/%2").arg(e.address.toString()).arg(e.bits);
    return text;
}

namespace {

// `bits` bits of payload from bit `offset` on (LSB first), as little-endian bytes.
QByteArray takeBits(const QByteArray &payload, int offset, int bits)
{
    QByteArray out((bits + 7) / 8, '\0');
    for (int i = 0; i < bits; ++i) {
        const int from = offset + i;
        if (quint8(payload.at(from / 8)) & (1u << (from % 8)))
            out[i / 8] = char(quint8(out.at(i / 8)) | (1u << (i % 8)));
    }
    return out;
}

} // namespace

Result<QList<PdoValue>> decodePdo(const PdoConfig &config, const QByteArray &payload,
                                  const ObjectDictionary &dictionary)
{
    const int needed = (config.totalBits() + 7) / 8;
    if (payload.size() < needed)
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1 carries %2 bytes, its mapping needs %3")
                         .arg(config.name())
                         .arg(payload.size())
                         .arg(needed));
    QList<PdoValue> values;
    int offset = 0;
    for (const PdoMappingEntry &e : config.entries) {
        const QByteArray bytes = takeBits(payload, offset, e.bits);
        offset += e.bits;
        if (e.isDummy() || e.bits == 0)
            continue;
        const ObjectDef *def = dictionary.find(e.address);
        if (!def || datatype::isVariableLength(def->type)) {
            quint64 v = 0;
            for (qsizetype i = qMin<qsizetype>(bytes.size(), 8) - 1; i >= 0; --i)
                v = (v << 8) | quint8(bytes.at(i));
            values.append(
                { e.address, def ? QVariant(bytes) : QVariant::fromValue<qulonglong>(v) });
            continue;
        }
        QByteArray sized = bytes;
        const int size = datatype::byteSize(def->type);
        if (size > 0)
            sized.resize(size, '\0');
        auto raw = codec::decode(def->type, sized);
        if (!raw)
            return raw.error().prefixed(Tr::tr("%1 %2").arg(config.name(), e.address.toString()));
        values.append({ e.address, raw.value() });
    }
    return values;
}

const PdoConfig *pdoForCanId(const QList<PdoConfig> &configs, quint32 canId)
{
    for (const PdoConfig &c : configs) {
        if (c.isEnabled() && c.canId() == canId)
            return &c;
    }
    return nullptr;
}

} // namespace db::canopen
