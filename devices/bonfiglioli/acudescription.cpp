#include "acudescription.h"

#include "description/descriptionfile.h"

namespace db::bonfiglioli {

Result<ObjectDictionary> loadAcuDictionary()
{
    return loadJsonDescription(QStringLiteral(":/devices/bonfiglioli/acu.json"));
}

const ObjectDictionary &acuDictionary()
{
    static const ObjectDictionary dict = [] {
        auto loaded = loadAcuDictionary();
        Q_ASSERT_X(loaded.ok(), "acuDictionary", qPrintable(loaded.error().toString()));
        return loaded.valueOr(ObjectDictionary());
    }();
    return dict;
}

bool hasDataSets(const ObjectDictionary &dictionary, quint16 parameter)
{
    return dictionary.contains(ObjectAddress(parameter, 1));
}

} // namespace db::bonfiglioli
