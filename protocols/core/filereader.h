#pragma once
// Reading whole files that users and other tools give us (descriptions, parameter sets,
// recordings, values): with a size limit, so that a wrong file (a video, a disk image) is
// refused with its size instead of filling memory, and with errors that name the file and the
// cause. Parsers report positions with textPosition().
#include "result.h"

#include <QByteArray>
#include <QString>

namespace db::files {

constexpr qint64 kMiB = 1024 * 1024;
constexpr qint64 kDescriptionLimit = 64 * kMiB; // EDS, DCF, XDD, XDC, JSON
constexpr qint64 kParameterSetLimit = 16 * kMiB;
constexpr qint64 kRecordingLimit = 1024 * kMiB; // scope CSV
constexpr qint64 kValueLimit = 16 * kMiB; // an object's value from a file (SDO's own limit)

// The whole file. Io error "cannot read PATH: cause" when it cannot be opened or read (a folder
// included); InvalidArgument "PATH is N MB, more than the M MB a ... may have" above maxBytes.
// `what` names the kind of file for that message ("a device description").
Result<QByteArray> readAll(const QString &path, qint64 maxBytes, const QString &what);

// "line L, column C" (1-based, columns in characters) of a byte offset into UTF-8 text.
QString textPosition(const QByteArray &text, qint64 offset);

} // namespace db::files
