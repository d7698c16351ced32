#pragma once

#include "core/objectdictionary.h"

#include <QHash>

#include <functional>

namespace db::sim {

// The simulated device's values: a volatile working set, a stored NVM image (1010h "save") and
// the factory values (description defaults plus the simulator's own choices). Values are raw
// QVariants in the codec's canonical types. Access rules are checked by checkRead/checkWrite;
// set() is the device's own path and ignores them.
class ObjectStore
{
public:
    ObjectStore(ObjectDictionary dictionary,
                const QHash<ObjectAddress, QVariant> &factoryOverrides);

    const ObjectDictionary &dictionary() const { return m_dictionary; }
    const ObjectDef *definition(ObjectAddress address) const { return m_dictionary.find(address); }

    QVariant value(ObjectAddress address) const { return m_values.value(address); }
    qint64 integer(ObjectAddress address) const { return m_values.value(address).toLongLong(); }
    double real(ObjectAddress address) const { return m_values.value(address).toDouble(); }
    // Normalises to the object's type; values that do not fit are saturated, unknown objects
    // are ignored.
    void set(ObjectAddress address, const QVariant &value);

    // "object 1234:0 does not exist", "6041:0 is read-only", range errors from ObjectDef.
    Result<void> checkRead(ObjectAddress address) const;
    Result<QVariant> checkWrite(ObjectAddress address, const QVariant &value) const;

    void storeToNvm(); // 1010h "save"
    void restoreFactory(const std::function<bool(ObjectAddress)> &keep); // 1011h "load"
    void loadFromNvm(); // power cycle

private:
    ObjectDictionary m_dictionary;
    QHash<ObjectAddress, QVariant> m_factory;
    QHash<ObjectAddress, QVariant> m_nvm;
    QHash<ObjectAddress, QVariant> m_values;
};

} // namespace db::sim
