#include "paramcomparepdf.h"

#include "core/printable.h"

#include <QCoreApplication>
#include <QDir>
#include <QLocale>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>

namespace db::widgets {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(ComparisonReport)
};

QString esc(const QString &text)
{
    return printable(text).toHtmlEscaped();
}

} // namespace

QString comparisonReportHtml(const ComparisonReportInfo &info, const ParameterComparison &c)
{
    QString html;
    html += QStringLiteral("<html><body style='font-family: sans-serif; font-size: 9pt;'>");
    html += QStringLiteral("<h2>%1</h2>").arg(esc(Tr::tr("Parameter Comparison")));
    html += QStringLiteral("<table cellspacing='0' cellpadding='2'>");
    const auto row = [&html](const QString &name, const QString &value) {
        if (!value.isEmpty())
            html += QStringLiteral("<tr><td>%1</td><td>%2</td></tr>").arg(esc(name), esc(value));
    };
    row(Tr::tr("Date:"), QLocale().toString(info.created, QLocale::LongFormat));
    row(Tr::tr("Device:"), info.device);
    row(Tr::tr("Vendor:"), info.vendor);
    row(Tr::tr("Product:"), info.product);
    row(Tr::tr("Revision:"), info.revision);
    row(Tr::tr("Serial number:"), info.serialNumber);
    row(Tr::tr("Parameter set:"), info.fileOrigin);
    row(Tr::tr("Compared with:"), info.referenceFile);
    row(Tr::tr("Result:"), c.countsText());
    html += QStringLiteral("</table>");
    if (!info.note.isEmpty())
        html += QStringLiteral("<p style='color:#b00000;'>%1</p>").arg(esc(info.note));

    QList<const CompareRow *> differing;
    for (const CompareRow &r : c.rows) {
        if (r.differs)
            differing.append(&r);
    }
    html += QStringLiteral("<h3>%1</h3>")
                .arg(esc(differing.isEmpty()
                             ? Tr::tr("No differences")
                             : Tr::tr("%n difference(s)", nullptr, int(differing.size()))));
    if (!differing.isEmpty()) {
        html += QStringLiteral("<table border='1' cellspacing='0' cellpadding='3' width='100%'>"
                               "<thead><tr>");
        QStringList header { Tr::tr("Address"), Tr::tr("Name") };
        header += c.sideNames;
        header << Tr::tr("Unit") << Tr::tr("Status");
        for (const QString &h : std::as_const(header))
            html += QStringLiteral("<th align='left'>%1</th>").arg(esc(h));
        html += QStringLiteral("</tr></thead>");
        for (const CompareRow *r : std::as_const(differing)) {
            html += QStringLiteral("<tr><td>%1</td><td>%2</td>")
                        .arg(esc(c.addressFormat->format(r->address)), esc(r->name));
            for (int side = 0; side < c.sideNames.size(); ++side)
                html += QStringLiteral("<td>%1</td>").arg(esc(r->valueText(side)));
            html += QStringLiteral("<td>%1</td><td>%2</td></tr>")
                        .arg(esc(r->unit), esc(compareStatusName(r->status)));
        }
        html += QStringLiteral("</table>");
    }
    html += QStringLiteral("</body></html>");
    return html;
}

Result<void> saveComparisonPdf(const QString &path, const ComparisonReportInfo &info,
                               const ParameterComparison &c)
{
    QSaveFile file(path);
    const auto failed = [&path](const QString &why) {
        return Error(Error::Kind::Io,
                     Tr::tr("Report not saved to %1: %2").arg(QDir::toNativeSeparators(path), why));
    };
    if (!file.open(QIODevice::WriteOnly))
        return failed(file.errorString());
    {
        QPdfWriter writer(&file);
        writer.setTitle(Tr::tr("Parameter Comparison"));
        writer.setCreator(QStringLiteral("drivebench"));
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
        writer.setResolution(300);
        QTextDocument document;
        document.setHtml(comparisonReportHtml(info, c));
        document.print(&writer);
    } // the writer finishes the file here
    if (file.error() != QFileDevice::NoError)
        return failed(file.errorString());
    if (!file.commit())
        return failed(file.errorString());
    return {};
}

} // namespace db::widgets
