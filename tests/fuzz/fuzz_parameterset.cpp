// Parameter-set files (backups, restores, comparisons). A set that parses must serialize to a
// file that parses again to the same entries.
#include "fuzzsupport.h"
#include "parameters/parameterset.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const Result<ParameterSet> set = ParameterSet::parse(bytes, QStringLiteral("fuzz.dbp"));
    if (!set)
        return 0;
    const Result<ParameterSet> again =
        ParameterSet::parse(set->serialize(), QStringLiteral("again"));
    if (!again)
        fuzz::finding("a parsed parameter set does not parse again after serialize()");
    if (again->size() != set->size())
        fuzz::finding("a parameter set changed its number of entries in serialize -> parse");
    return 0;
}
