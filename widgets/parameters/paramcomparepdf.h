#pragma once

// The comparison of a parameter set as a PDF for the commissioning record: who was compared
// (the device's identity and connection, the file or files), when, the counts, and every row
// whose values differ, with each side's value and the unit.

#include "core/result.h"
#include "parameters/parameterset.h"

#include <QDateTime>
#include <QString>

namespace db::widgets {

struct ComparisonReportInfo
{
    QString device; // the connection's URI; empty when two files were compared
    // The device's identity as read (or the reference file's): "Fullmo (000002D6h)".
    QString vendor;
    QString product;
    QString revision;
    QString serialNumber;
    QString fileOrigin; // the set compared
    QString referenceFile; // the file in the device's place, if any
    QString note; // a warning to print with the result (another unit), may be empty
    QDateTime created;
};

// The report as HTML (what the PDF shows).
QString comparisonReportHtml(const ComparisonReportInfo &info, const ParameterComparison &c);
// Writes the PDF (A4) atomically: a failure leaves an existing file as it was and names the
// cause.
Result<void> saveComparisonPdf(const QString &path, const ComparisonReportInfo &info,
                               const ParameterComparison &c);

} // namespace db::widgets
