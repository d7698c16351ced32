// Our own JSON device description format (built-in descriptions and user files).
#include "description/descriptionfile.h"
#include "fuzzsupport.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    (void)parseJsonDescription(bytes, QStringLiteral("fuzz.json"));
    return 0;
}
