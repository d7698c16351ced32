#include "builtindescriptions.h"

#include "description/descriptionfile.h"

#include <QDir>

namespace db::resources {

Result<ObjectDictionary> builtinDescription(const QString &name)
{
    return loadJsonDescription(QStringLiteral(":/devices/%1.json").arg(name));
}

QStringList builtinDescriptionNames()
{
    QStringList names;
    for (const QString &file :
         QDir(QStringLiteral(":/devices")).entryList({ QStringLiteral("*.json") }))
        names.append(file.chopped(5));
    return names;
}

const ObjectDictionary &movingCapDictionary()
{
    // Compiled in and tested (tst_builtindescriptions): a failure here is a build defect.
    static const ObjectDictionary dict = [] {
        auto loaded = builtinDescription(QStringLiteral("movingcap_eth"));
        Q_ASSERT_X(loaded.ok(), "movingCapDictionary", qPrintable(loaded.error().toString()));
        return loaded.valueOr(ObjectDictionary());
    }();
    return dict;
}

} // namespace db::resources
