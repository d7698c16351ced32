#include "vabuscodec.h"

#include "core/valuecodec.h"

#include <QCoreApplication>

namespace db::vabus {

QString errorText(quint16 code)
{
    // Error table of chapter 7.2; the same codes appear in parameter 11.
    const char *text = nullptr;
    switch (code) {
    case NoError:
        text = QT_TRANSLATE_NOOP("VABus", "no error");
        break;
    case InvalidValue:
        text = QT_TRANSLATE_NOOP("VABus", "invalid parameter value");
        break;
    case InvalidDataSet:
        text = QT_TRANSLATE_NOOP("VABus", "invalid data set");
        break;
    case NotReadable:
        text = QT_TRANSLATE_NOOP("VABus", "parameter not readable (write-only)");
        break;
    case NotWritable:
        text = QT_TRANSLATE_NOOP("VABus", "parameter not writable (read-only)");
        break;
    case EepromReadError:
        text = QT_TRANSLATE_NOOP("VABus", "EEPROM read error");
        break;
    case EepromWriteError:
        text = QT_TRANSLATE_NOOP("VABus", "EEPROM write error");
        break;
    case EepromChecksumError:
        text = QT_TRANSLATE_NOOP("VABus", "EEPROM checksum error");
        break;
    case NotWritableWhileRunning:
        text = QT_TRANSLATE_NOOP("VABus", "parameter not writable while the drive is running");
        break;
    case DataSetsDiffer:
        text = QT_TRANSLATE_NOOP("VABus", "values of the data sets differ");
        break;
    case 10:
    case 12:
        text = QT_TRANSLATE_NOOP("VABus", "not available");
        break;
    case UnknownParameter:
        text = QT_TRANSLATE_NOOP("VABus", "unknown parameter");
        break;
    case SyntaxError:
    case SyntaxError2:
        text = QT_TRANSLATE_NOOP("VABus", "syntax error in received telegram");
        break;
    case LengthMismatch:
        text = QT_TRANSLATE_NOOP("VABus",
                                 "data type of the parameter does not match the number "
                                 "of bytes in the telegram");
        break;
    case UnknownError:
        text = QT_TRANSLATE_NOOP("VABus", "unknown error");
        break;
    case NodeNotAvailable:
        text = QT_TRANSLATE_NOOP("VABus", "selected system bus node not available");
        break;
    default:
        return QCoreApplication::translate("VABus", "error code %1 (not in the VABus error table)")
            .arg(code);
    }
    return QCoreApplication::translate("VABus", text);
}

quint16 Telegram::errorCode() const
{
    if (data.size() != 2)
        return 0;
    return quint16(quint8(data.at(0)) | (quint8(data.at(1)) << 8));
}

Telegram Telegram::readRequest(quint16 parameter, quint8 dataSet, quint8 sys)
{
    return Telegram { false, false, sys, dataSet, parameter, {} };
}

Telegram Telegram::writeRequest(quint16 parameter, quint8 dataSet, const QByteArray &data,
                                quint8 sys)
{
    return Telegram { true, false, sys, dataSet, parameter, data };
}

Telegram Telegram::errorAnswer(const Telegram &request, quint16 code)
{
    QByteArray data;
    data.append(char(code & 0xFF));
    data.append(char(code >> 8));
    return Telegram { request.write, true, request.sys, request.dataSet, request.parameter, data };
}

Result<QByteArray> encode(const Telegram &t)
{
    if (t.data.size() > kMaxDataBytes)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("a VABus telegram carries at most %1 data bytes, not %2")
                         .arg(kMaxDataBytes)
                         .arg(t.data.size()));
    if (t.error && t.data.size() != 2)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("a VABus error answer carries a 2-byte error code"));
    if (t.parameter > kMaxParameter)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("VABus parameter numbers end at %1, not %2")
                         .arg(kMaxParameter)
                         .arg(t.parameter));
    QByteArray out;
    out.reserve(kMinTelegramBytes + t.data.size());
    out.append(char((t.write ? kRwBit : 0) | (t.error ? kErrorBit : 0)));
    out.append(char(kAddressBytes + t.data.size()));
    out.append(char(t.sys));
    out.append(char(t.dataSet));
    out.append(char(t.parameter & 0xFF));
    out.append(char(t.parameter >> 8));
    out.append(t.data);
    return out;
}

Result<Telegram> decode(const QByteArray &bytes)
{
    if (bytes.size() < kMinTelegramBytes)
        return Error(Error::Kind::Malformed,
                     QStringLiteral("VABus telegram of %1 bytes is shorter than %2 (%3)")
                         .arg(bytes.size())
                         .arg(kMinTelegramBytes)
                         .arg(hex(bytes)));
    const quint8 header = quint8(bytes.at(0));
    const int nob = quint8(bytes.at(1));
    if (header & ~(kRwBit | kErrorBit))
        return Error(Error::Kind::Malformed,
                     QStringLiteral("VABus header 0x%1 has bits 5..0 set")
                         .arg(header, 2, 16, QLatin1Char('0')));
    if (nob + 2 != bytes.size())
        return Error(Error::Kind::Malformed,
                     QStringLiteral("VABus NoB %1 does not match a telegram of %2 bytes")
                         .arg(nob)
                         .arg(bytes.size()));
    Telegram t;
    t.write = header & kRwBit;
    t.error = header & kErrorBit;
    t.sys = quint8(bytes.at(2));
    t.dataSet = quint8(bytes.at(3));
    t.parameter = quint16(quint8(bytes.at(4)) | (quint8(bytes.at(5)) << 8));
    t.data = bytes.mid(kMinTelegramBytes);
    if (t.error && t.data.size() != 2)
        return Error(Error::Kind::Malformed,
                     QStringLiteral("VABus error answer with NoB %1 instead of 6").arg(nob));
    return t;
}

bool isCarried(DataType type)
{
    if (type == DataType::VisibleString)
        return true;
    const int size = datatype::byteSize(type);
    return datatype::isInteger(type) && (size == 2 || size == 4);
}

Result<QByteArray> encodeValue(DataType type, const QVariant &raw)
{
    if (!isCarried(type))
        return Error(Error::Kind::NotSupported,
                     QStringLiteral("VABus carries 16- and 32-bit integers and strings, not %1")
                         .arg(datatype::name(type)));
    if (type == DataType::VisibleString) {
        // An empty string is a select telegram without data bytes (NoB 4): the length of a
        // string is NoB - 4, with no terminator.
        const QByteArray text = raw.toString().toLatin1();
        if (text.size() > kMaxDataBytes)
            return Error(Error::Kind::OutOfRange,
                         QStringLiteral("a VABus string has at most %1 characters, not %2")
                             .arg(kMaxDataBytes)
                             .arg(text.size()));
        return text;
    }
    return codec::encode(type, raw);
}

Result<QVariant> decodeValue(DataType type, const QByteArray &data)
{
    if (type == DataType::VisibleString)
        return QVariant(QString::fromLatin1(data));
    if (!isCarried(type))
        return Error(Error::Kind::NotSupported,
                     QStringLiteral("VABus carries 16- and 32-bit integers and strings, not %1")
                         .arg(datatype::name(type)));
    if (data.size() != datatype::byteSize(type))
        return Error(Error::Kind::Malformed,
                     QStringLiteral("%1 data bytes for a %2 parameter (expected %3)")
                         .arg(data.size())
                         .arg(datatype::name(type))
                         .arg(datatype::byteSize(type)));
    return codec::decode(type, data);
}

DataType typeForSize(qsizetype bytes)
{
    if (bytes == 2)
        return DataType::Integer16;
    if (bytes == 4)
        return DataType::Integer32;
    return DataType::VisibleString;
}

QString hex(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

} // namespace db::vabus
