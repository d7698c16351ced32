// Scope recordings imported from CSV. A recording that loads must export to CSV that loads.
#include "fuzzsupport.h"
#include "scope/csv.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const Result<scope::Recording> rec = scope::csv::fromCsv(bytes);
    if (!rec)
        return 0;
    if (!scope::csv::fromCsv(scope::csv::toCsv(*rec)))
        fuzz::finding("an imported recording does not import again after export");
    return 0;
}
