#pragma once

#include "core/objectdictionary.h"

#include <QMap>
#include <QStringList>

#include <optional>

namespace db {

// What loading a device description gives: the dictionary plus everything the file said that
// does not fit it, and the problems found on the way. Real-world files are often sloppy; a
// loader reports what it had to guess or skip as warnings (one line each, naming the section or
// object) and fails only when the file is unreadable, not a description, or has no objects.
struct DescriptionLoad
{
    enum class Format { Eds, Dcf, Xdd, Xdc, Json };

    ObjectDictionary dictionary;
    QStringList warnings;
    Format format = Format::Eds;

    // Defaults written as "$NODEID+0x180" (CiA 306 4.6.2 / CiA 311): the constant part, by
    // address. They are resolved into dictionary defaults whenever a node id is known (given to
    // the loader or stated by a DCF/XDC); otherwise those defaults stay invalid until
    // resolveNodeId() is called.
    QMap<ObjectAddress, qlonglong> nodeIdDefaults;
    // Configured values of a DCF (ParameterValue) or XDC (actualValue), raw.
    QMap<ObjectAddress, QVariant> values;
    // DCF [DeviceComissioning] / XDC deviceCommissioning, when stated (node id 1..127).
    std::optional<quint8> nodeId;
    std::optional<quint32> bitrateKbit;
    int typeDefinitions = 0; // DEFTYPE/DEFSTRUCT entries (described, not loaded as objects)

    // Fills every $NODEID default for this node id; returns false (with a warning added) for
    // results that do not fit their object's type.
    bool resolveNodeId(quint8 nodeId);
};

struct DescriptionOptions
{
    // Evaluates $NODEID expressions; when empty the file's own commissioning node id is used,
    // and failing that they stay symbolic (DescriptionLoad::nodeIdDefaults).
    std::optional<quint8> nodeId;
};

QString formatName(DescriptionLoad::Format format); // "EDS", "DCF", "XDD", "XDC", "JSON"

// Chooses the loader by content (XML -> XDD/XDC, JSON -> ours, INI -> EDS/DCF) and names the
// format by extension. Errors name the file and the cause.
Result<DescriptionLoad> loadDeviceDescription(const QString &path,
                                              const DescriptionOptions &options = {});
Result<DescriptionLoad> parseDeviceDescription(const QByteArray &data, const QString &origin,
                                               const DescriptionOptions &options = {});

// Value syntax shared by the EDS and XDD loaders (CiA 306 4.6.2, CiA 311 6.4.5).
namespace description {

struct ParsedValue
{
    QVariant raw; // invalid when empty, symbolic or broken
    bool nodeIdRelative = false; // "$NODEID+x": raw is invalid, offset holds x
    qlonglong offset = 0;
    QString error; // non-empty: could not be used
};

// Integer text: decimal, "0x" hex, and (CiA 306 only, allowOctal) octal with a leading 0.
std::optional<qlonglong> parseInteger(const QString &text, bool allowOctal);
// A DefaultValue/LowLimit/HighLimit/ParameterValue for an object of this type. With nodeId
// set, $NODEID expressions are evaluated; without, they come back as nodeIdRelative.
ParsedValue parseValue(DataType type, const QString &text, std::optional<quint8> nodeId,
                       bool allowOctal);
// Raw -> the text CiA 306 wants in a DCF ("0x" hex for unsigned, decimal for signed, hex bytes
// for OCTET_STRING/DOMAIN); parseValue() reads it back to the same raw value.
QString valueText(DataType type, const QVariant &raw);
// Text from a file of unknown encoding: UTF-8 (BOM stripped) when valid, else Latin-1.
QString decodeText(const QByteArray &bytes);
// True when the bytes cannot be a text description (NUL bytes, mostly control characters).
bool looksBinary(const QByteArray &bytes);

} // namespace description
} // namespace db
