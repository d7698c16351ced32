#include "descriptions.h"

#include "devices/nm17x/nm17xdescription.h"
#include "resources/builtindescriptions.h"

#include <QSettings>
#include <QStandardPaths>

namespace db::app {

namespace {

constexpr quint32 kMovingCapVendorId = 0x0000053B; // Fullmo GmbH

DescriptionLibrary makeLibrary()
{
    DescriptionLibrary library;
    for (const nm17x::Variant v :
         { nm17x::Variant::Nm170, nm17x::Variant::Nm172, nm17x::Variant::Nm174 }) {
        library.addBuiltin({ nm17x::variantName(v), QStringLiteral("built-in"), nm17x::kVendorId,
                             nm17x::productCode(v), std::nullopt,
                             [v](quint8 node) -> Result<ObjectDictionary> {
                                 return nm17x::dictionary(v, node);
                             } });
    }
    // One description for the whole MovingCap ETH family (the product code names the model).
    library.addBuiltin({ QStringLiteral("MovingCap ETH"), QStringLiteral("built-in"),
                         kMovingCapVendorId, std::nullopt, std::nullopt,
                         [](quint8) -> Result<ObjectDictionary> {
                             return resources::movingCapDictionary();
                         } });
    return library;
}

} // namespace

QString descriptionFolder()
{
    const QString env = qEnvironmentVariable("DRIVEBENCH_DESCRIPTIONS");
    if (!env.isEmpty())
        return env;
    const QSettings settings(QSettings::IniFormat, QSettings::UserScope,
                             QStringLiteral("drivebench"), QStringLiteral("drivebench"));
    const QString configured = settings.value(QStringLiteral("descriptions/folder")).toString();
    if (!configured.isEmpty())
        return configured;
    // One folder for the GUI, the CLI and the simulator, whatever the program's name.
    const QString data = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    return data.isEmpty() ? QString() : data + QStringLiteral("/drivebench/descriptions");
}

DescriptionLibrary &descriptionLibrary()
{
    static DescriptionLibrary library = makeLibrary();
    return library;
}

} // namespace db::app
