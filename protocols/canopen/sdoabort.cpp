#include "sdoabort.h"

#include <QHash>

namespace db::canopen {

QString abortText(quint32 code)
{
    static const QHash<quint32, const char *> texts = {
        { abort::ToggleNotAlternated, "toggle bit not alternated" },
        { abort::Timeout, "SDO protocol timed out" },
        { abort::InvalidCommand, "client/server command specifier not valid or unknown" },
        { abort::InvalidBlockSize, "invalid block size (block mode only)" },
        { abort::InvalidSequence, "invalid sequence number (block mode only)" },
        { abort::CrcError, "CRC error (block mode only)" },
        { abort::OutOfMemory, "out of memory" },
        { abort::UnsupportedAccess, "unsupported access to an object" },
        { abort::WriteOnly, "attempt to read a write only object" },
        { abort::ReadOnly, "attempt to write a read only object" },
        { abort::NoSuchObject, "object does not exist in the object dictionary" },
        { abort::NotMappable, "object cannot be mapped to the PDO" },
        { abort::PdoTooLong,
          "the number and length of the objects to be mapped would exceed the "
          "PDO length" },
        { abort::Incompatible, "general parameter incompatibility" },
        { abort::InternalIncompatibility, "general internal incompatibility in the device" },
        { abort::HardwareError, "access failed due to a hardware error" },
        { abort::LengthMismatch,
          "data type does not match, length of service parameter does not "
          "match" },
        { abort::LengthTooHigh, "data type does not match, length of service parameter too high" },
        { abort::LengthTooLow, "data type does not match, length of service parameter too low" },
        { abort::NoSuchSubIndex, "sub-index does not exist" },
        { abort::InvalidValue, "invalid value for parameter (download only)" },
        { abort::ValueTooHigh, "value of parameter written too high (download only)" },
        { abort::ValueTooLow, "value of parameter written too low (download only)" },
        { abort::MaxBelowMin, "maximum value is less than minimum value" },
        { abort::ResourceNotAvailable, "resource not available: SDO connection" },
        { abort::General, "general error" },
        { abort::CannotStore, "data cannot be transferred or stored to the application" },
        { abort::CannotStoreLocal,
          "data cannot be transferred or stored to the application "
          "because of local control" },
        { abort::CannotStoreState,
          "data cannot be transferred or stored to the application "
          "because of the present device state" },
        { abort::NoDictionary,
          "object dictionary dynamic generation fails or no object "
          "dictionary is present" },
        { abort::NoData, "no data available" },
    };
    const auto it = texts.constFind(code);
    if (it != texts.cend())
        return QString::fromLatin1(*it);
    return QStringLiteral("unknown abort code 0x%1").arg(code, 8, 16, QLatin1Char('0'));
}

} // namespace db::canopen
