#pragma once

#include "devicedescription.h"

namespace db {

// CiA 306 electronic data sheets (EDS) and device configuration files (DCF): INI text, read
// tolerantly. Accepted and reported as warnings where they deviate from CiA 306: missing fields
// (sensible defaults), unparsable values (dropped), $NODEID expressions, octal/hex/decimal
// numbers, CompactSubObj arrays (expanded to sub-indices "Name1".."NameN", names from
// [xxxxName]), objects missing from or missing in the object lists, SubNumber and sub-index 0
// that disagree with the sub-indices present, duplicate keys and sections (the last wins), CRLF,
// a UTF-8 BOM and Latin-1 text. Non-standard keys Unit, Factor and Description are taken when
// present. DEFTYPE/DEFSTRUCT entries are counted, not loaded.
//
// Fails only when the data is not an EDS at all: no INI sections, or no object sections.
Result<DescriptionLoad> loadEds(const QString &path, const DescriptionOptions &options = {});
Result<DescriptionLoad> parseEds(const QByteArray &data, const QString &origin,
                                 const DescriptionOptions &options = {});

} // namespace db
