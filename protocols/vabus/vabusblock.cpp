#include "vabusblock.h"

#include "core/valuecodec.h"

namespace db::vabus {

namespace {

constexpr int kGroupChars = 5;
constexpr quint16 kMaxBlockParameter = 999; // three digits in a group
constexpr quint8 kMaxBlockDataSet = 4;

int hexDigits(DataType type)
{
    return datatype::byteSize(type) * 2;
}

} // namespace

bool fitsBlock(const BlockItem &item)
{
    const int size = datatype::byteSize(item.type);
    return item.address.index <= kMaxBlockParameter && item.address.sub <= kMaxBlockDataSet
        && (size == 2 || size == 4) && item.type != DataType::Real32;
}

QList<BlockItem> packBlock(const QList<BlockItem> &candidates)
{
    QList<BlockItem> items;
    int definition = 0;
    int answer = 0;
    for (const BlockItem &item : candidates) {
        if (!fitsBlock(item) || definition + kGroupChars > kMaxBlockChars
            || answer + hexDigits(item.type) > kMaxBlockChars)
            continue;
        definition += kGroupChars;
        answer += hexDigits(item.type);
        items.append(item);
    }
    return items;
}

Result<QByteArray> blockDefinition(const QList<BlockItem> &items)
{
    QByteArray text;
    for (const BlockItem &item : items) {
        if (!fitsBlock(item))
            return Error(Error::Kind::InvalidArgument,
                         QStringLiteral("parameter %1:%2 cannot be part of a block (numbers up to "
                                        "999, data sets 0-4, words and double words only)")
                             .arg(item.address.index)
                             .arg(item.address.sub));
        text += '0';
        text += char('0' + item.address.sub);
        text += QByteArray::number(item.address.index).rightJustified(3, '0');
    }
    if (text.isEmpty() || text.size() > kMaxBlockChars)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("a block definition takes 1 to %1 parameters, not %2")
                         .arg(kMaxBlockChars / kGroupChars)
                         .arg(items.size()));
    return text;
}

Result<QList<QVariant>> decodeBlock(const QByteArray &text, const QList<BlockItem> &items)
{
    int expected = 0;
    for (const BlockItem &item : items)
        expected += hexDigits(item.type);
    if (text.size() != expected)
        return Error(Error::Kind::Malformed,
                     QStringLiteral("block answer has %1 characters, the block needs %2")
                         .arg(text.size())
                         .arg(expected));
    QList<QVariant> values;
    qsizetype pos = 0;
    for (const BlockItem &item : items) {
        const int digits = hexDigits(item.type);
        bool ok = false;
        const qulonglong bits = text.mid(pos, digits).toULongLong(&ok, 16);
        if (!ok)
            return Error(Error::Kind::Malformed,
                         QStringLiteral("block answer '%1' is not hexadecimal at character %2")
                             .arg(QString::fromLatin1(text))
                             .arg(pos + 1));
        pos += digits;
        QByteArray littleEndian;
        for (int i = 0; i < digits / 2; ++i)
            littleEndian.append(char((bits >> (8 * i)) & 0xFF));
        auto value = codec::decode(item.type, littleEndian);
        if (!value)
            return value.error();
        values.append(value.value());
    }
    return values;
}

} // namespace db::vabus
