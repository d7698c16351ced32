#pragma once

#include "core/objectdictionary.h"
#include "core/result.h"

#include <QByteArray>
#include <QString>

namespace db {

// drivebench's own JSON device description (resources/devices/*.json; the format is described
// in descriptionfile.cpp). Errors name the file and the offending object.
Result<ObjectDictionary> loadJsonDescription(const QString &path);
Result<ObjectDictionary> parseJsonDescription(const QByteArray &json, const QString &origin);

} // namespace db
