// EDS/DCF files from other tools: the INI reader and the EDS loader (with and without a node id
// for $NODEID expressions). Text may be any bytes: UTF-8, Latin-1 or binary junk.
#include "description/edsinifile.h"
#include "description/edsloader.h"
#include "fuzzsupport.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    QStringList warnings;
    (void)eds::IniFile::parse(QString::fromUtf8(bytes), &warnings);
    (void)parseEds(bytes, QStringLiteral("fuzz.eds"));
    DescriptionOptions withNode;
    withNode.nodeId = 5;
    (void)parseEds(bytes, QStringLiteral("fuzz.dcf"), withNode);
    return 0;
}
