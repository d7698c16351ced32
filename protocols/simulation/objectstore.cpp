#include "objectstore.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::simulation)
};
} // namespace

namespace db::sim {

namespace {
QVariant zeroOf(DataType type)
{
    if (type == DataType::Boolean)
        return false;
    if (datatype::isSignedInteger(type))
        return QVariant::fromValue<qlonglong>(0);
    if (datatype::isUnsignedInteger(type))
        return QVariant::fromValue<qulonglong>(0);
    if (datatype::isReal(type))
        return 0.0;
    if (type == DataType::VisibleString || type == DataType::UnicodeString)
        return QString();
    return QByteArray();
}
} // namespace

ObjectStore::ObjectStore(ObjectDictionary dictionary,
                         const QHash<ObjectAddress, QVariant> &factoryOverrides)
    : m_dictionary(std::move(dictionary))
{
    for (const ObjectDef &def : m_dictionary.objects()) {
        QVariant v = factoryOverrides.value(def.address, def.defaultValue);
        auto normalized =
            v.isValid() ? codec::normalize(def.type, v) : Result<QVariant>(QVariant());
        m_factory.insert(def.address,
                         normalized.ok() && normalized->isValid() ? normalized.value()
                                                                  : zeroOf(def.type));
    }
    m_values = m_factory;
    m_nvm = m_factory;
}

void ObjectStore::set(ObjectAddress address, const QVariant &value)
{
    const ObjectDef *def = definition(address);
    if (!def)
        return;
    auto normalized = codec::normalize(def->type, value);
    if (normalized) {
        m_values.insert(address, normalized.value());
        return;
    }
    // Saturate computed values that overflow the type (e.g. a position beyond INTEGER32).
    const QVariant lo = codec::typeMinimum(def->type);
    const QVariant hi = codec::typeMaximum(def->type);
    if (lo.isValid() && hi.isValid()) {
        const double d = value.toDouble();
        m_values.insert(address, d < lo.toDouble() ? lo : hi);
    }
}

Result<void> ObjectStore::checkRead(ObjectAddress address) const
{
    const ObjectDef *def = definition(address);
    if (!def)
        return Error(
            Error::Kind::InvalidArgument,
            Tr::tr("object %1 does not exist").arg(m_dictionary.addressFormat().format(address)));
    if (!def->readable())
        return Error(Error::Kind::AccessDenied,
                     Tr::tr("%1 is write-only").arg(m_dictionary.addressFormat().format(address)));
    return {};
}

Result<QVariant> ObjectStore::checkWrite(ObjectAddress address, const QVariant &value) const
{
    const ObjectDef *def = definition(address);
    if (!def)
        return Error(
            Error::Kind::InvalidArgument,
            Tr::tr("object %1 does not exist").arg(m_dictionary.addressFormat().format(address)));
    if (!def->writable())
        return Error(Error::Kind::AccessDenied,
                     Tr::tr("%1 is read-only").arg(m_dictionary.addressFormat().format(address)));
    return def->validate(value, m_dictionary.addressFormat());
}

void ObjectStore::storeToNvm()
{
    for (const ObjectDef &def : m_dictionary.objects()) {
        if (def.storable)
            m_nvm.insert(def.address, m_values.value(def.address));
    }
}

void ObjectStore::restoreFactory(const std::function<bool(ObjectAddress)> &keep)
{
    for (const ObjectDef &def : m_dictionary.objects()) {
        if (!def.storable || (keep && keep(def.address)))
            continue;
        m_values.insert(def.address, m_factory.value(def.address));
        m_nvm.insert(def.address, m_factory.value(def.address));
    }
}

void ObjectStore::loadFromNvm()
{
    for (const ObjectDef &def : m_dictionary.objects())
        m_values.insert(def.address,
                        def.storable ? m_nvm.value(def.address) : m_factory.value(def.address));
}

} // namespace db::sim
