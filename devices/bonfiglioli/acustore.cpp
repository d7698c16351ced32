#include "acustore.h"

#include "core/valuecodec.h"
#include "vabus/vabuscodec.h"

namespace db::bonfiglioli {

using namespace db::vabus;

AcuStore::AcuStore(const ObjectDictionary &description)
{
    for (const ObjectDef &def : description.objects()) {
        Param &p = m_params[def.address.index];
        p.type = def.type;
        p.access = def.access;
        p.min = def.minimum;
        p.max = def.maximum;
        if (def.address.sub > 0)
            p.dataSets = true;
    }
    for (const ObjectDef &def : description.objects()) {
        const Param &p = m_params[def.address.index];
        if (p.dataSets && def.address.sub == 0)
            continue;
        QVariant raw = def.defaultValue;
        if (!raw.isValid() && p.type == DataType::VisibleString) {
            raw = QString();
        } else if (!raw.isValid()) {
            // No default given: 0, or the nearest limit when 0 is outside the range.
            raw = codec::normalize(p.type, 0).valueOr({});
            if (p.min.isValid() && !codec::checkLimits(p.type, raw, p.min, {}))
                raw = p.min;
            else if (p.max.isValid() && !codec::checkLimits(p.type, raw, {}, p.max))
                raw = p.max;
        }
        m_eeprom.insert(key(def.address.index, def.address.sub), raw);
    }
    m_ram = m_eeprom;
}

bool AcuStore::hasDataSets(quint16 parameter) const
{
    return m_params.value(parameter).dataSets;
}

DataType AcuStore::type(quint16 parameter) const
{
    return m_params.value(parameter).type;
}

AcuStore::Outcome AcuStore::read(quint16 parameter, quint8 dataSet) const
{
    if (dataSet > kMaxReadDataSet)
        return { InvalidDataSet, {} };
    const auto it = m_params.constFind(parameter);
    if (it == m_params.cend())
        return { UnknownParameter, {} };
    if (it->access == Access::WriteOnly)
        return { NotReadable, {} };
    if (!it->dataSets && dataSet != 0)
        return { InvalidDataSet, {} };
    QVariant raw;
    if (it->dataSets && dataSet == 0) {
        raw = m_ram.value(key(parameter, 1));
        for (quint8 ds = 2; ds <= 4; ++ds) {
            if (m_ram.value(key(parameter, ds)) != raw)
                return { DataSetsDiffer, {} };
        }
    } else {
        raw = m_ram.value(key(parameter, dataSet));
    }
    if (it->type == DataType::VisibleString) // an empty string is a telegram without data
        return { NoError, raw.toString().toLatin1() };
    auto data = encodeValue(it->type, raw);
    if (!data)
        return { UnknownError, {} };
    return { NoError, data.value() };
}

AcuStore::Outcome AcuStore::write(quint16 parameter, quint8 dataSet, const QByteArray &data,
                                  bool running)
{
    if (dataSet > kMaxWriteDataSet)
        return { InvalidDataSet, {} };
    const auto it = m_params.constFind(parameter);
    if (it == m_params.cend())
        return { UnknownParameter, {} };
    if (it->access == Access::ReadOnly || it->access == Access::Const)
        return { NotWritable, {} };
    const bool ram = dataSet > kMaxReadDataSet;
    const quint8 target = ram ? quint8(dataSet - kRamDataSetOffset) : dataSet;
    if (!it->dataSets && target != 0)
        return { InvalidDataSet, {} };
    QVariant raw;
    if (it->type == DataType::VisibleString) {
        if (data.size() > it->maxLength)
            return { InvalidValue, {} };
        raw = QString::fromLatin1(data);
    } else {
        if (data.size() != datatype::byteSize(it->type))
            return { LengthMismatch, {} };
        auto decoded = decodeValue(it->type, data);
        if (!decoded || !codec::checkLimits(it->type, decoded.value(), it->min, it->max))
            return { InvalidValue, {} };
        raw = decoded.value();
    }
    if (running && it->lockedWhileRunning)
        return { NotWritableWhileRunning, {} };
    const QList<quint8> sets =
        it->dataSets && target == 0 ? QList<quint8> { 1, 2, 3, 4 } : QList<quint8> { target };
    for (const quint8 ds : sets) {
        m_ram.insert(key(parameter, ds), raw);
        if (!ram)
            m_eeprom.insert(key(parameter, ds), raw);
    }
    if (!ram)
        ++m_eepromWrites;
    return { NoError, data };
}

void AcuStore::set(quint16 parameter, quint8 dataSet, const QVariant &raw)
{
    const QList<quint8> sets = hasDataSets(parameter) && dataSet == 0 ? QList<quint8> { 1, 2, 3, 4 }
                                                                      : QList<quint8> { dataSet };
    for (const quint8 ds : sets) {
        m_ram.insert(key(parameter, ds), raw);
        m_eeprom.insert(key(parameter, ds), raw);
    }
}

QVariant AcuStore::value(quint16 parameter, quint8 dataSet) const
{
    return m_ram.value(key(parameter, dataSet));
}

void AcuStore::setLimits(quint16 parameter, const QVariant &min, const QVariant &max)
{
    m_params[parameter].min = min;
    m_params[parameter].max = max;
}

void AcuStore::setLockedWhileRunning(quint16 parameter)
{
    m_params[parameter].lockedWhileRunning = true;
}

void AcuStore::setMaxLength(quint16 parameter, int characters)
{
    m_params[parameter].maxLength = characters;
}

void AcuStore::powerCycle()
{
    m_ram = m_eeprom;
}

} // namespace db::bonfiglioli
