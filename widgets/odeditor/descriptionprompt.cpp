#include "descriptionprompt.h"

#include "description/descriptionlibrary.h"
#include "widgets/common/widgetstyle.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMimeData>
#include <QPushButton>

namespace db::widgets {

namespace {
QString hex32(quint32 v)
{
    return QString::number(v, 16).rightJustified(8, QLatin1Char('0')).toUpper() + QLatin1Char('h');
}
} // namespace

DescriptionPrompt::DescriptionPrompt(QWidget *parent)
    : QFrame(parent)
    , m_text(new QLabel(this))
    , m_browse(new QPushButton(tr("Browse…"), this))
{
    setObjectName(QStringLiteral("descriptionPrompt"));
    m_text->setObjectName(QStringLiteral("descriptionPromptText"));
    m_browse->setObjectName(QStringLiteral("descriptionBrowse"));
    setFrameShape(QFrame::StyledPanel);
    setAcceptDrops(true);
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_browse->setToolTip(tr("Choose the device's description file (EDS, DCF, XDD, XDC or "
                            "drivebench JSON); it is also added to the description library"));
    auto *layout = new QHBoxLayout(this);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_browse, 0, Qt::AlignTop);
    connect(m_browse, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Description of the device"),
                                                          QString(), fileFilter());
        if (!path.isEmpty())
            Q_EMIT fileChosen(path);
    });
    hide();
}

QString DescriptionPrompt::fileFilter()
{
    return tr("Device descriptions (*.eds *.dcf *.xdd *.xdc *.json);;All files (*)");
}

QString DescriptionPrompt::droppedDescription(const QMimeData *data)
{
    if (!data || !data->hasUrls() || data->urls().size() != 1)
        return {};
    const QUrl url = data->urls().constFirst();
    if (!url.isLocalFile())
        return {};
    const QString path = url.toLocalFile();
    const QString suffix = QFileInfo(path).suffix().toLower();
    for (const QString &pattern : DescriptionLibrary::filePatterns()) {
        if (pattern.toLower() == QStringLiteral("*.") + suffix)
            return path;
    }
    return {};
}

void DescriptionPrompt::dragEnterEvent(QDragEnterEvent *event)
{
    if (!droppedDescription(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void DescriptionPrompt::dropEvent(QDropEvent *event)
{
    const QString path = droppedDescription(event->mimeData());
    if (path.isEmpty())
        return;
    event->acceptProposedAction();
    Q_EMIT fileChosen(path); // loaded and checked by whoever listens, like Browse…
}

void DescriptionPrompt::showFor(const DeviceConnection *connection)
{
    if (!connection || !connection->isConnected() || !connection->dictionary().isEmpty()) {
        hide();
        return;
    }
    const DeviceIdentity &id = connection->dictionary().identity;
    QString device;
    if (id.vendorId != 0) {
        device =
            tr("It reports vendor %1, product %2").arg(hex32(id.vendorId), hex32(id.productCode));
        device += id.revision.isEmpty()
            ? QStringLiteral(".")
            : tr(", revision %1.")
                  .arg(parseRevision(id.revision) ? hex32(*parseRevision(id.revision))
                                                  : id.revision);
    } else {
        device = tr("It did not report its identity (1018h).");
    }
    m_text->setText(tr("<b>No description for this device.</b> %1 No description in the library "
                       "matches it, so its objects are not listed; read and write them with "
                       "<i>By index…</i>, or choose its description file (Browse… or drop it "
                       "here).")
                        .arg(device.toHtmlEscaped()));
    style::setTextColor(m_text, QColor());
    show();
}

void DescriptionPrompt::showProblem(const QString &text)
{
    m_text->setText(text.toHtmlEscaped());
    style::setTextColor(m_text, style::errorColor());
    show();
}

QString DescriptionPrompt::text() const
{
    return m_text->text();
}

} // namespace db::widgets
