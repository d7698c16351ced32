// ScopePage: CSV and image export (the image with a header naming devices, time and trigger).
#include "scopepage.h"

#include "core/filewriter.h"

#include "scope/csv.h"
#include "scope/recorder.h"
#include "scopeplot.h"
#include "widgets/common/plot.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <QComboBox>
#include <QDateTime>
#include <QFileDialog>
#include <QFileInfo>
#include <QTemporaryFile>

namespace db::widgets {

Result<void> ScopePage::exportCsv(const QString &fileName, bool visibleRangeOnly) const
{
    if (visibleRangeOnly)
        return scope::csv::save(fileName, m_recorder->recording(), m_plot->timeLower(),
                                m_plot->timeUpper());
    return scope::csv::save(fileName, m_recorder->recording());
}

Result<void> ScopePage::exportImage(const QString &fileName) const
{
    QCustomPlot *plot = m_plot->customPlot();
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    if (suffix != QLatin1String("pdf") && suffix != QLatin1String("png"))
        return Error(Error::Kind::InvalidArgument,
                     tr("%1: choose a .png or .pdf file name").arg(fileName));
    // QCustomPlot writes by file name, so the image goes to a temporary file next to the
    // target that then replaces it in one rename: an export that fails or is interrupted
    // leaves the old file as it was and no half-written image.
    db::files::removeStaleTemporaries(fileName); // what a killed export left
    QTemporaryFile temp(db::files::temporaryTemplate(fileName));
    if (!temp.open())
        return Error(Error::Kind::Io,
                     tr("%1: cannot be written: %2").arg(fileName, temp.errorString()));
    temp.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ReadGroup
                        | QFileDevice::ReadOther);
    temp.close();
    // The header goes above the lanes for the export only.
    auto *header = new QCPTextElement(plot, exportHeader().join(QLatin1Char('\n')), font());
    header->setTextFlags(Qt::AlignLeft | Qt::AlignVCenter);
    header->setMargins(QMargins(8, 4, 8, 2));
    plot->plotLayout()->insertRow(0);
    plot->plotLayout()->addElement(0, 0, header);
    plot->plotLayout()->setRowStretchFactor(0, 0.001);
    const bool ok = suffix == QLatin1String("pdf") ? plot->savePdf(temp.fileName())
                                                   : plot->savePng(temp.fileName(), 0, 0, 2.0);
    plot->plotLayout()->remove(header);
    plot->plotLayout()->simplify();
    plot->replot(QCustomPlot::rpQueuedReplot);
    if (!ok)
        return Error(Error::Kind::Io, tr("%1: cannot be written").arg(fileName));
    if (std::rename(QFile::encodeName(temp.fileName()).constData(),
                    QFile::encodeName(fileName).constData())
        != 0)
        return Error(
            Error::Kind::Io,
            tr("%1: cannot be written: %2").arg(fileName, QString::fromLocal8Bit(strerror(errno))));
    temp.setAutoRemove(false); // renamed: nothing left to remove
    return {};
}

QStringList ScopePage::exportHeader() const
{
    QStringList devices;
    for (int i = 0; i < m_recorder->channelCount(); ++i) {
        const scope::ChannelInfo &info = m_recorder->channelInfo(i);
        const QString name = info.deviceName.isEmpty() ? info.device : info.deviceName;
        if (!name.isEmpty() && !devices.contains(name))
            devices.append(name);
    }
    QStringList lines;
    if (devices.isEmpty())
        lines.append(tr("Device: none"));
    else if (devices.size() == 1)
        lines.append(tr("Device: %1").arg(devices.constFirst()));
    else
        lines.append(tr("Devices: %1").arg(devices.join(QStringLiteral(", "))));
    const QDateTime started = m_recorder->startedAt();
    if (started.isValid())
        lines.append(
            tr("Recorded: %1")
                .arg(started.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"))));
    const scope::Trigger &t = m_recorder->trigger();
    const double at = m_recorder->triggerTime();
    if (t.isValid() && t.channel < m_recorder->channelCount() && std::isfinite(at)) {
        const scope::ChannelInfo &info = m_recorder->channelInfo(t.channel);
        QString condition = m_triggerKindBox->itemText(int(t.kind));
        const auto value = [&info](double v) {
            return info.unit.isEmpty() ? QString::number(v)
                                       : QStringLiteral("%1 %2").arg(QString::number(v), info.unit);
        };
        if (t.kind == scope::Trigger::Kind::BitSet || t.kind == scope::Trigger::Kind::BitClear)
            condition = QStringLiteral("%1 %2").arg(condition).arg(t.bit);
        else if (t.kind == scope::Trigger::Kind::WindowInside
                 || t.kind == scope::Trigger::Kind::WindowOutside)
            condition =
                QStringLiteral("%1 %2 … %3").arg(condition, value(t.level), value(t.level2));
        else
            condition = QStringLiteral("%1 %2").arg(condition, value(t.level));
        lines.append(tr("Trigger: %1, %2; %3 s before, %4 s after; time 0 = trigger")
                         .arg(scopeChannelName(*m_recorder, t.channel), condition)
                         .arg(t.preTriggerS)
                         .arg(t.postTriggerS));
    } else {
        lines.append(tr("No trigger: time from the start of the recording"));
    }
    return lines;
}

void ScopePage::promptExportCsv(bool visibleRangeOnly)
{
    const QString file =
        QFileDialog::getSaveFileName(this, tr("Export recording"), {}, tr("CSV (*.csv)"));
    if (file.isEmpty())
        return;
    const Result<void> r = exportCsv(file, visibleRangeOnly);
    showMessage(r ? tr("Saved %1").arg(QFileInfo(file).fileName()) : r.error().message(), !r);
}

void ScopePage::promptExportImage()
{
    const QString file = QFileDialog::getSaveFileName(this, tr("Export image"), {},
                                                      tr("PNG image (*.png);;PDF (*.pdf)"));
    if (file.isEmpty())
        return;
    const Result<void> r = exportImage(file);
    showMessage(r ? tr("Saved %1").arg(QFileInfo(file).fileName()) : r.error().message(), !r);
}

} // namespace db::widgets
