// XDD/XDC device descriptions (XML) from other tools.
#include "description/xddloader.h"
#include "fuzzsupport.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    DescriptionOptions options;
    options.nodeId = 5;
    (void)parseXdd(bytes, QStringLiteral("fuzz.xdd"), options);
    return 0;
}
