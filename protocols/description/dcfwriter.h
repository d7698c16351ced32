#pragma once

#include "core/objectdictionary.h"

#include <QDateTime>

namespace db {

// [DeviceComissioning] of a DCF (CiA 306 4.7; the misspelling is the standard's key).
struct DcfCommissioning
{
    quint8 nodeId = 0; // 1..127; 0 = not stated
    quint32 bitrateKbit = 0; // 0 = not stated
    QString nodeName;
};

// A CiA 306 device configuration file for one device: [FileInfo], [DeviceInfo] with the
// identity the device reported (1018h sub-indices 1-3 in `values`), else the dictionary's, and
// without the numbers neither knows (never a made-up 0 or a revision that is not a number),
// [DeviceComissioning], the object lists and one section per object (and sub-index) with its
// description and, where `values` has one, its ParameterValue (raw -> text by
// description::valueText()). Values for addresses the dictionary does not know are left out. Text
// is UTF-8; line breaks inside strings become spaces (an INI value is one line). Pure; `now` stamps
// the creation date.
QByteArray dcfText(const ObjectDictionary &dictionary, const QMap<ObjectAddress, QVariant> &values,
                   const DcfCommissioning &commissioning,
                   const QDateTime &now = QDateTime::currentDateTime());

// Writes dcfText() atomically (QSaveFile): the file is either the complete new DCF or untouched.
Result<void> writeDcf(const QString &path, const ObjectDictionary &dictionary,
                      const QMap<ObjectAddress, QVariant> &values,
                      const DcfCommissioning &commissioning);

} // namespace db
