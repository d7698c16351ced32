#include "sdoabort.h"

#include <QCoreApplication>
#include <QHash>

namespace db::canopen {

// The CiA 301 texts of the abort codes, translated like every other message.
QString abortText(quint32 code)
{
    static const QHash<quint32, const char *> texts = {
        { abort::ToggleNotAlternated,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "toggle bit not alternated") },
        { abort::Timeout, QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "SDO protocol timed out") },
        { abort::InvalidCommand,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "client/server command specifier not valid or unknown") },
        { abort::InvalidBlockSize,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "invalid block size (block mode only)") },
        { abort::InvalidSequence,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "invalid sequence number (block mode only)") },
        { abort::CrcError,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "CRC error (block mode only)") },
        { abort::OutOfMemory, QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "out of memory") },
        { abort::UnsupportedAccess,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "unsupported access to an object") },
        { abort::WriteOnly,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "attempt to read a write only object") },
        { abort::ReadOnly,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "attempt to write a read only object") },
        { abort::NoSuchObject,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "object does not exist in the object dictionary") },
        { abort::NotMappable,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "object cannot be mapped to the PDO") },
        { abort::PdoTooLong,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "the number and length of the objects to be mapped would exceed the "
                            "PDO length") },
        { abort::Incompatible,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "general parameter incompatibility") },
        { abort::InternalIncompatibility,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "general internal incompatibility in the device") },
        { abort::HardwareError,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "access failed due to a hardware error") },
        { abort::LengthMismatch,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "data type does not match, length of service parameter does not "
                            "match") },
        { abort::LengthTooHigh,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "data type does not match, length of service parameter too high") },
        { abort::LengthTooLow,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "data type does not match, length of service parameter too low") },
        { abort::NoSuchSubIndex,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "sub-index does not exist") },
        { abort::InvalidValue,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "invalid value for parameter (download only)") },
        { abort::ValueTooHigh,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "value of parameter written too high (download only)") },
        { abort::ValueTooLow,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "value of parameter written too low (download only)") },
        { abort::MaxBelowMin,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "maximum value is less than minimum value") },
        { abort::ResourceNotAvailable,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "resource not available: SDO connection") },
        { abort::General, QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "general error") },
        { abort::CannotStore,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "data cannot be transferred or stored to the application") },
        { abort::CannotStoreLocal,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "data cannot be transferred or stored to the application "
                            "because of local control") },
        { abort::CannotStoreState,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "data cannot be transferred or stored to the application "
                            "because of the present device state") },
        { abort::NoDictionary,
          QT_TRANSLATE_NOOP("db::canopen::SdoAbort",
                            "object dictionary dynamic generation fails or no object "
                            "dictionary is present") },
        { abort::NoData, QT_TRANSLATE_NOOP("db::canopen::SdoAbort", "no data available") },
    };
    const auto it = texts.constFind(code);
    if (it != texts.cend())
        return QCoreApplication::translate("db::canopen::SdoAbort", *it);
    return QCoreApplication::translate("db::canopen::SdoAbort", "unknown abort code 0x%1")
        .arg(code, 8, 16, QLatin1Char('0'));
}

} // namespace db::canopen
