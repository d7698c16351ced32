#include "valuecodec.h"

#include <QRegularExpression>
#include <QtEndian>

#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db::codec {

namespace {

Error outOfRange(DataType type, const QString &value)
{
    return Error(Error::Kind::OutOfRange,
                 Tr::tr("%1 does not fit %2 (%3 .. %4)")
                     .arg(value, datatype::name(type), typeMinimum(type).toString(),
                          typeMaximum(type).toString()));
}

Error notANumber(DataType type, const QString &text)
{
    return Error(Error::Kind::InvalidArgument,
                 Tr::tr("'%1' is not a valid %2 value").arg(text, datatype::name(type)));
}

qint64 signedMin(int bytes)
{
    return bytes >= 8 ? std::numeric_limits<qint64>::min() : -(qint64(1) << (bytes * 8 - 1));
}

qint64 signedMax(int bytes)
{
    return bytes >= 8 ? std::numeric_limits<qint64>::max() : (qint64(1) << (bytes * 8 - 1)) - 1;
}

quint64 unsignedMax(int bytes)
{
    return bytes >= 8 ? std::numeric_limits<quint64>::max() : (quint64(1) << (bytes * 8)) - 1;
}

// Parses an integer literal into sign + magnitude so that the full qint64/quint64 range works.
bool parseIntegerLiteral(QString text, bool *negative, quint64 *magnitude, int *baseOut)
{
    text = text.trimmed().remove(QLatin1Char('_'));
    *negative = false;
    if (text.startsWith(QLatin1Char('-')) || text.startsWith(QLatin1Char('+'))) {
        *negative = text.startsWith(QLatin1Char('-'));
        text = text.mid(1).trimmed();
    }
    if (text.isEmpty())
        return false;
    int base = 10;
    if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
        base = 16;
        text = text.mid(2);
    } else if (text.startsWith(QLatin1String("0b"), Qt::CaseInsensitive)) {
        base = 2;
        text = text.mid(2);
    } else if (text.endsWith(QLatin1Char('h'), Qt::CaseInsensitive)) {
        base = 16;
        text.chop(1);
    }
    bool ok = false;
    *magnitude = text.toULongLong(&ok, base);
    *baseOut = base;
    return ok && !text.isEmpty();
}

} // namespace

QVariant typeMinimum(DataType type)
{
    const int size = datatype::byteSize(type);
    if (datatype::isSignedInteger(type))
        return QVariant::fromValue<qlonglong>(signedMin(size));
    if (datatype::isUnsignedInteger(type))
        return QVariant::fromValue<qulonglong>(0);
    if (type == DataType::Boolean)
        return false;
    if (type == DataType::Real32)
        return double(-std::numeric_limits<float>::max());
    if (type == DataType::Real64)
        return -std::numeric_limits<double>::max();
    return {};
}

QVariant typeMaximum(DataType type)
{
    const int size = datatype::byteSize(type);
    if (datatype::isSignedInteger(type))
        return QVariant::fromValue<qlonglong>(signedMax(size));
    if (datatype::isUnsignedInteger(type))
        return QVariant::fromValue<qulonglong>(unsignedMax(size));
    if (type == DataType::Boolean)
        return true;
    if (type == DataType::Real32)
        return double(std::numeric_limits<float>::max());
    if (type == DataType::Real64)
        return std::numeric_limits<double>::max();
    return {};
}

Result<QVariant> normalize(DataType type, const QVariant &value)
{
    if (!value.isValid())
        return Error(Error::Kind::InvalidArgument, Tr::tr("no value"));
    const int size = datatype::byteSize(type);
    const int id = value.typeId();
    if (id == QMetaType::QString && datatype::isNumeric(type))
        return fromText(type, value.toString());

    if (type == DataType::Boolean) {
        if (id == QMetaType::Bool)
            return value;
        bool ok = false;
        const qlonglong v = value.toLongLong(&ok);
        if (!ok || (v != 0 && v != 1))
            return outOfRange(type, value.toString());
        return QVariant(v == 1);
    }
    if (datatype::isSignedInteger(type)) {
        qlonglong v = 0;
        if (id == QMetaType::ULongLong || id == QMetaType::ULong || id == QMetaType::UInt) {
            const qulonglong u = value.toULongLong();
            if (u > qulonglong(signedMax(size)))
                return outOfRange(type, value.toString());
            v = qlonglong(u);
        } else if (id == QMetaType::Double || id == QMetaType::Float) {
            const double d = value.toDouble();
            if (d != std::floor(d))
                return notANumber(type, value.toString());
            if (d < double(signedMin(size)) || d > double(signedMax(size)))
                return outOfRange(type, value.toString());
            v = qlonglong(d);
        } else {
            bool ok = false;
            v = value.toLongLong(&ok);
            if (!ok)
                return notANumber(type, value.toString());
        }
        if (v < signedMin(size) || v > signedMax(size))
            return outOfRange(type, QString::number(v));
        return QVariant::fromValue<qlonglong>(v);
    }
    if (datatype::isUnsignedInteger(type)) {
        qulonglong v = 0;
        if (id == QMetaType::LongLong || id == QMetaType::Long || id == QMetaType::Int
            || id == QMetaType::Short || id == QMetaType::Char || id == QMetaType::SChar) {
            const qlonglong s = value.toLongLong();
            if (s < 0)
                return outOfRange(type, QString::number(s));
            v = qulonglong(s);
        } else if (id == QMetaType::Double || id == QMetaType::Float) {
            const double d = value.toDouble();
            if (d != std::floor(d))
                return notANumber(type, value.toString());
            if (d < 0 || d > double(unsignedMax(size)))
                return outOfRange(type, value.toString());
            v = qulonglong(d);
        } else {
            bool ok = false;
            v = value.toULongLong(&ok);
            if (!ok)
                return notANumber(type, value.toString());
        }
        if (v > unsignedMax(size))
            return outOfRange(type, QString::number(v));
        return QVariant::fromValue<qulonglong>(v);
    }
    if (datatype::isReal(type)) {
        bool ok = false;
        const double d = value.toDouble(&ok);
        if (!ok)
            return notANumber(type, value.toString());
        if (type == DataType::Real32 && std::isfinite(d)
            && std::fabs(d) > double(std::numeric_limits<float>::max()))
            return outOfRange(type, value.toString());
        return QVariant(type == DataType::Real32 ? double(float(d)) : d);
    }
    if (type == DataType::VisibleString) {
        const QString s = value.toString();
        for (QChar c : s) {
            if (c.unicode() > 0x7E
                || (c.unicode() < 0x20 && c != QLatin1Char('\t') && c != QLatin1Char('\n')
                    && c != QLatin1Char('\r')))
                return Error(Error::Kind::InvalidArgument,
                             Tr::tr("VISIBLE_STRING allows printable ASCII only; "
                                    "'%1' is not")
                                 .arg(c));
        }
        return QVariant(s);
    }
    if (type == DataType::UnicodeString)
        return QVariant(value.toString());
    // OCTET_STRING, DOMAIN
    if (id == QMetaType::QByteArray)
        return value;
    if (id == QMetaType::QString)
        return fromText(type, value.toString());
    return Error(Error::Kind::InvalidArgument, Tr::tr("%1 needs bytes").arg(datatype::name(type)));
}

Result<QByteArray> encode(DataType type, const QVariant &raw)
{
    const auto norm = normalize(type, raw);
    if (!norm)
        return norm.error();
    const QVariant &v = norm.value();
    const int size = datatype::byteSize(type);
    QByteArray out(size, '\0');
    auto *p = reinterpret_cast<uchar *>(out.data());
    if (type == DataType::Boolean) {
        out[0] = v.toBool() ? 1 : 0;
    } else if (datatype::isInteger(type)) {
        const quint64 bits =
            datatype::isSignedInteger(type) ? quint64(v.toLongLong()) : v.toULongLong();
        for (int i = 0; i < size; ++i)
            p[i] = uchar(bits >> (8 * i));
    } else if (type == DataType::Real32) {
        qToLittleEndian(float(v.toDouble()), p);
    } else if (type == DataType::Real64) {
        qToLittleEndian(v.toDouble(), p);
    } else if (type == DataType::VisibleString) {
        out = v.toString().toLatin1();
    } else if (type == DataType::UnicodeString) {
        const QString s = v.toString();
        out.resize(s.size() * 2);
        for (qsizetype i = 0; i < s.size(); ++i)
            qToLittleEndian(s.at(i).unicode(), out.data() + 2 * i);
    } else {
        out = v.toByteArray();
    }
    return out;
}

Result<QVariant> decode(DataType type, const QByteArray &bytes)
{
    const int size = datatype::byteSize(type);
    if (size > 0 && bytes.size() != size) {
        return Error(Error::Kind::Malformed,
                     Tr::tr("%1 needs %2 bytes, got %3")
                         .arg(datatype::name(type))
                         .arg(size)
                         .arg(bytes.size()));
    }
    const auto *p = reinterpret_cast<const uchar *>(bytes.constData());
    if (type == DataType::Boolean) {
        if (p[0] > 1)
            return Error(
                Error::Kind::Malformed,
                Tr::tr("BOOLEAN byte is 0x%1, not 0 or 1").arg(p[0], 2, 16, QLatin1Char('0')));
        return QVariant(p[0] == 1);
    }
    if (datatype::isInteger(type)) {
        quint64 bits = 0;
        for (int i = 0; i < size; ++i)
            bits |= quint64(p[i]) << (8 * i);
        if (datatype::isUnsignedInteger(type))
            return QVariant::fromValue<qulonglong>(bits);
        if (size < 8 && (bits & (quint64(1) << (size * 8 - 1))))
            bits |= ~quint64(0) << (size * 8); // sign-extend
        return QVariant::fromValue<qlonglong>(qint64(bits));
    }
    if (type == DataType::Real32)
        return QVariant(double(qFromLittleEndian<float>(p)));
    if (type == DataType::Real64)
        return QVariant(qFromLittleEndian<double>(p));
    if (type == DataType::VisibleString) {
        const qsizetype nul = bytes.indexOf('\0');
        return QVariant(QString::fromLatin1(nul >= 0 ? bytes.left(nul) : bytes));
    }
    if (type == DataType::UnicodeString) {
        if (bytes.size() % 2 != 0)
            return Error(
                Error::Kind::Malformed,
                Tr::tr("UNICODE_STRING has an odd number of bytes (%1)").arg(bytes.size()));
        QString s;
        s.reserve(bytes.size() / 2);
        for (qsizetype i = 0; i + 1 < bytes.size(); i += 2) {
            const char16_t c = qFromLittleEndian<char16_t>(bytes.constData() + i);
            if (c == 0)
                break;
            s.append(QChar(c));
        }
        return QVariant(s);
    }
    return QVariant(bytes);
}

Result<QVariant> fromText(DataType type, const QString &text)
{
    const QString t = text.trimmed();
    if (type == DataType::Boolean) {
        const QString l = t.toLower();
        if (l == QLatin1String("1") || l == QLatin1String("true") || l == QLatin1String("on"))
            return QVariant(true);
        if (l == QLatin1String("0") || l == QLatin1String("false") || l == QLatin1String("off"))
            return QVariant(false);
        return notANumber(type, text);
    }
    if (datatype::isInteger(type)) {
        bool negative = false;
        quint64 magnitude = 0;
        int base = 10;
        if (!parseIntegerLiteral(t, &negative, &magnitude, &base))
            return notANumber(type, text);
        const int size = datatype::byteSize(type);
        if (datatype::isSignedInteger(type) && base != 10 && !negative
            && magnitude <= unsignedMax(size)) {
            // A hex or binary literal is a bit pattern of the type's width: 0xFFFF = -1 (INT16).
            quint64 bits = magnitude;
            if (size < 8 && (bits & (quint64(1) << (size * 8 - 1))))
                bits |= ~quint64(0) << (size * 8);
            return normalize(type, QVariant::fromValue<qlonglong>(qint64(bits)));
        }
        if (datatype::isUnsignedInteger(type)) {
            if (negative && magnitude != 0)
                return outOfRange(type, t);
            return normalize(type, QVariant::fromValue<qulonglong>(magnitude));
        }
        if (negative) {
            if (magnitude > quint64(std::numeric_limits<qint64>::max()) + 1)
                return outOfRange(type, t);
            return normalize(type, QVariant::fromValue<qlonglong>(qint64(0 - magnitude)));
        }
        if (magnitude > quint64(std::numeric_limits<qint64>::max()))
            return outOfRange(type, t);
        return normalize(type, QVariant::fromValue<qlonglong>(qint64(magnitude)));
    }
    if (datatype::isReal(type)) {
        bool ok = false;
        const double d = t.toDouble(&ok);
        if (!ok)
            return notANumber(type, text);
        return normalize(type, d);
    }
    if (type == DataType::VisibleString || type == DataType::UnicodeString)
        return normalize(type, text); // strings are taken as typed, spaces included
    // OCTET_STRING / DOMAIN: hex bytes
    QString hex = t;
    static const QRegularExpression separators(QStringLiteral("[\\s:,-]"));
    hex.remove(separators);
    if (hex.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        hex = hex.mid(2);
    static const QRegularExpression hexOnly(QStringLiteral("^[0-9a-fA-F]*$"));
    if (hex.size() % 2 != 0 || !hexOnly.match(hex).hasMatch())
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("'%1' is not a list of hex bytes (e.g. 01 02 FF)").arg(text));
    return QVariant(QByteArray::fromHex(hex.toLatin1()));
}

QString toText(DataType type, const QVariant &raw, TextFormat format)
{
    if (!raw.isValid())
        return {};
    if (type == DataType::Boolean)
        return raw.toBool() ? QStringLiteral("1") : QStringLiteral("0");
    if (datatype::isInteger(type)) {
        if (format == TextFormat::Hex) {
            const int size = datatype::byteSize(type);
            quint64 bits =
                datatype::isSignedInteger(type) ? quint64(raw.toLongLong()) : raw.toULongLong();
            if (size < 8)
                bits &= (quint64(1) << (size * 8)) - 1;
            return QStringLiteral("0x")
                + QString::number(bits, 16).toUpper().rightJustified(size * 2, QLatin1Char('0'));
        }
        return datatype::isSignedInteger(type) ? QString::number(raw.toLongLong())
                                               : QString::number(raw.toULongLong());
    }
    if (datatype::isReal(type)) {
        const double d = raw.toDouble();
        // QString::number() prints -0.0 as "0", which parses back to +0.0: other bits than
        // the device sent, e.g. when a backup is restored.
        if (d == 0 && std::signbit(d))
            return QStringLiteral("-0");
        return QString::number(d, 'g', type == DataType::Real32 ? 9 : 17);
    }
    if (type == DataType::VisibleString || type == DataType::UnicodeString)
        return raw.toString();
    return QString::fromLatin1(raw.toByteArray().toHex(' ').toUpper());
}

Result<void> checkLimits(DataType type, const QVariant &raw, const QVariant &min,
                         const QVariant &max)
{
    if (!datatype::isNumeric(type) || type == DataType::Boolean)
        return {};
    auto below = [&](const QVariant &limit) {
        if (datatype::isSignedInteger(type))
            return raw.toLongLong() < limit.toLongLong();
        if (datatype::isUnsignedInteger(type))
            return raw.toULongLong() < limit.toULongLong();
        return raw.toDouble() < limit.toDouble();
    };
    auto above = [&](const QVariant &limit) {
        if (datatype::isSignedInteger(type))
            return raw.toLongLong() > limit.toLongLong();
        if (datatype::isUnsignedInteger(type))
            return raw.toULongLong() > limit.toULongLong();
        return raw.toDouble() > limit.toDouble();
    };
    if ((min.isValid() && below(min)) || (max.isValid() && above(max))) {
        return Error(Error::Kind::OutOfRange,
                     Tr::tr("%1 is outside the object's range %2 .. %3")
                         .arg(toText(type, raw),
                              min.isValid() ? toText(type, min) : QStringLiteral("-"),
                              max.isValid() ? toText(type, max) : QStringLiteral("-")));
    }
    return {};
}

double toPhysical(const QVariant &raw, double factor, double offset)
{
    return raw.toDouble() * factor + offset;
}

Result<QVariant> fromPhysical(DataType type, double physical, double factor, double offset)
{
    if (factor == 0.0)
        return Error(Error::Kind::InvalidArgument, Tr::tr("scaling factor is 0"));
    double raw = (physical - offset) / factor;
    if (!std::isfinite(raw))
        return Error(Error::Kind::InvalidArgument, Tr::tr("value is not finite"));
    if (datatype::isInteger(type) || type == DataType::Boolean) {
        raw = std::round(raw);
        const double lo = typeMinimum(type).toDouble();
        const double hi = typeMaximum(type).toDouble();
        if (raw < lo || raw > hi)
            return outOfRange(type, QString::number(physical));
        if (datatype::isUnsignedInteger(type))
            return normalize(type, QVariant::fromValue<qulonglong>(qulonglong(raw)));
        return normalize(type, QVariant::fromValue<qlonglong>(qlonglong(raw)));
    }
    if (datatype::isReal(type))
        return normalize(type, raw);
    return Error(Error::Kind::NotSupported,
                 Tr::tr("%1 has no physical value").arg(datatype::name(type)));
}

} // namespace db::codec
