#pragma once

// Block access (8.2): parameter 17 takes a block definition, a string of "Sdnnn" groups (S =
// system bus node, always '0'; d = data set 0-4; nnn = the parameter number in three digits);
// parameter 19 then answers the values of all of them in one string of upper-case hex digits,
// most significant first, 4 per word and 8 per double word. The definition and the answer are
// at most 64 characters; parameters from 1000 on and strings cannot be part of a block.

#include "core/datatype.h"
#include "core/objectaddress.h"
#include "core/result.h"

#include <QByteArray>
#include <QList>
#include <QVariant>

namespace db::vabus {

constexpr quint16 kBlockDefinitionParameter = 17;
constexpr quint16 kBlockWriteParameter = 18;
constexpr quint16 kBlockReadParameter = 19;
constexpr int kMaxBlockChars = 64;

struct BlockItem
{
    ObjectAddress address; // parameter number and data set 0-4
    DataType type = DataType::Unsigned16; // a 2- or 4-byte type
};

// Whether an item can be part of a block (parameter < 1000, data set 0-4, word/double word).
bool fitsBlock(const BlockItem &item);
// The items that fit, in order, as long as both the definition and the answer stay within
// 64 characters.
QList<BlockItem> packBlock(const QList<BlockItem> &candidates);
// "00411002600021000210" for 411, 260, 210, 210:2. InvalidArgument when an item does not fit
// or the text would exceed 64 characters.
Result<QByteArray> blockDefinition(const QList<BlockItem> &items);
// The answer of parameter 19 -> one raw value per item (the codec's canonical type). Malformed
// when the length does not match the items or a character is not a hex digit.
Result<QList<QVariant>> decodeBlock(const QByteArray &text, const QList<BlockItem> &items);

} // namespace db::vabus
