#include "objectdictionary.h"

#include <QCoreApplication>

namespace db {

void ObjectDictionary::insert(const ObjectDef &def)
{
    m_objects.insert(def.address, def);
}

const ObjectDef *ObjectDictionary::find(ObjectAddress address) const
{
    const auto it = m_objects.constFind(address);
    return it == m_objects.cend() ? nullptr : &it.value();
}

QList<ObjectDef> ObjectDictionary::subObjects(quint16 index) const
{
    QList<ObjectDef> result;
    for (auto it = m_objects.lowerBound(ObjectAddress(index, 0));
         it != m_objects.cend() && it.key().index == index; ++it)
        result.append(it.value());
    return result;
}

std::optional<ErrorCodeDef> ObjectDictionary::errorCode(quint32 code) const
{
    const auto it = m_errors.constFind(code);
    if (it == m_errors.cend())
        return std::nullopt;
    return *it;
}

QString ObjectDictionary::errorText(quint32 code) const
{
    if (const auto def = errorCode(code))
        return def->text.isEmpty() ? def->name : localText(def->text, def->localTexts);
    return cia301ErrorClassText(quint16(code));
}

QString cia301ErrorClassText(quint16 code)
{
    if (code == 0x0000)
        return QCoreApplication::translate("db::Cia301", "no error / error reset");
    const struct
    {
        quint16 mask;
        quint16 value;
        const char *text;
    } classes[] = {
        { 0xFF00, 0x1000, QT_TRANSLATE_NOOP("db::Cia301", "generic error") },
        { 0xFF00, 0x2100, QT_TRANSLATE_NOOP("db::Cia301", "current, device input side") },
        { 0xFF00, 0x2200, QT_TRANSLATE_NOOP("db::Cia301", "current inside the device") },
        { 0xFF00, 0x2300, QT_TRANSLATE_NOOP("db::Cia301", "current, device output side") },
        { 0xF000, 0x2000, QT_TRANSLATE_NOOP("db::Cia301", "current") },
        { 0xFF00, 0x3100, QT_TRANSLATE_NOOP("db::Cia301", "mains voltage") },
        { 0xFF00, 0x3200, QT_TRANSLATE_NOOP("db::Cia301", "voltage inside the device") },
        { 0xFF00, 0x3300, QT_TRANSLATE_NOOP("db::Cia301", "output voltage") },
        { 0xF000, 0x3000, QT_TRANSLATE_NOOP("db::Cia301", "voltage") },
        { 0xFF00, 0x4100, QT_TRANSLATE_NOOP("db::Cia301", "ambient temperature") },
        { 0xFF00, 0x4200, QT_TRANSLATE_NOOP("db::Cia301", "device temperature") },
        { 0xF000, 0x4000, QT_TRANSLATE_NOOP("db::Cia301", "temperature") },
        { 0xFF00, 0x5000, QT_TRANSLATE_NOOP("db::Cia301", "device hardware") },
        { 0xFF00, 0x6100, QT_TRANSLATE_NOOP("db::Cia301", "internal software") },
        { 0xFF00, 0x6200, QT_TRANSLATE_NOOP("db::Cia301", "user software") },
        { 0xFF00, 0x6300, QT_TRANSLATE_NOOP("db::Cia301", "data set") },
        { 0xF000, 0x6000, QT_TRANSLATE_NOOP("db::Cia301", "device software") },
        { 0xFF00, 0x7000, QT_TRANSLATE_NOOP("db::Cia301", "additional modules") },
        { 0xF000, 0x7000, QT_TRANSLATE_NOOP("db::Cia301", "additional modules") },
        { 0xFF00, 0x8100, QT_TRANSLATE_NOOP("db::Cia301", "communication") },
        { 0xFFFF, 0x8110, QT_TRANSLATE_NOOP("db::Cia301", "CAN overrun (objects lost)") },
        { 0xFFFF, 0x8120, QT_TRANSLATE_NOOP("db::Cia301", "CAN in error passive mode") },
        { 0xFFFF, 0x8130, QT_TRANSLATE_NOOP("db::Cia301", "life guard or heartbeat error") },
        { 0xFFFF, 0x8140, QT_TRANSLATE_NOOP("db::Cia301", "recovered from bus off") },
        { 0xFF00, 0x8200, QT_TRANSLATE_NOOP("db::Cia301", "protocol error") },
        { 0xF000, 0x8000, QT_TRANSLATE_NOOP("db::Cia301", "monitoring") },
        { 0xFF00, 0x9000, QT_TRANSLATE_NOOP("db::Cia301", "external error") },
        { 0xFF00, 0xF000, QT_TRANSLATE_NOOP("db::Cia301", "additional functions") },
        { 0xFF00, 0xFF00, QT_TRANSLATE_NOOP("db::Cia301", "device specific") },
    };
    // most specific mask first
    for (quint16 mask : { quint16(0xFFFF), quint16(0xFF00), quint16(0xF000) }) {
        for (const auto &c : classes) {
            if (c.mask == mask && (code & c.mask) == c.value)
                return QCoreApplication::translate("db::Cia301", c.text);
        }
    }
    return QCoreApplication::translate("db::Cia301", "unknown error 0x%1")
        .arg(code, 4, 16, QLatin1Char('0'));
}

} // namespace db
