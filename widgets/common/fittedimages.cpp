#include "fittedimages.h"

#include <QAbstractTextDocumentLayout>
#include <QEvent>
#include <QImage>
#include <QPixmap>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextImageFormat>
#include <QUrl>

namespace db::widgets {

FittedImages::FittedImages(QTextBrowser *browser)
    : QObject(browser)
    , m_browser(browser)
{
    browser->viewport()->installEventFilter(this);
    connect(browser, &QTextBrowser::sourceChanged, this, [this] {
        m_width = -1;
        fit();
    });
}

void FittedImages::install(QTextBrowser *browser)
{
    if (browser && !browser->findChild<FittedImages *>(QString(), Qt::FindDirectChildrenOnly))
        new FittedImages(browser);
}

bool FittedImages::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Resize)
        fit();
    return QObject::eventFilter(watched, event);
}

QImage FittedImages::imageOf(const QString &name) const
{
    // Cached by the document once laid out, else loaded the way the browser loads it
    // (relative to its source).
    QVariant resource = m_browser->document()->resource(QTextDocument::ImageResource, QUrl(name));
    if (!resource.isValid())
        resource = m_browser->loadResource(QTextDocument::ImageResource, QUrl(name));
    if (resource.canConvert<QImage>() && !resource.value<QImage>().isNull())
        return resource.value<QImage>();
    if (resource.typeId() == QMetaType::QPixmap)
        return resource.value<QPixmap>().toImage();
    return QImage::fromData(resource.toByteArray());
}

void FittedImages::fit()
{
    QTextDocument *doc = m_browser->document();
    // The room for an image: the viewport less the document's margins on both sides and a
    // little for the paragraph's own (Markdown image paragraphs have some).
    const int room = m_browser->viewport()->width() - 2 * int(doc->documentMargin()) - 32;
    if (room <= 0 || room == m_width)
        return;
    m_width = room;
    for (QTextBlock block = doc->begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (!fragment.isValid() || !fragment.charFormat().isImageFormat())
                continue;
            QTextImageFormat format = fragment.charFormat().toImageFormat();
            const QImage image = imageOf(format.name());
            if (image.isNull() || image.width() <= 0)
                continue;
            const int width = qMin(image.width(), room);
            format.setWidth(width);
            format.setHeight(double(image.height()) * width / image.width());
            QTextCursor cursor(doc);
            cursor.setPosition(fragment.position());
            cursor.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
            cursor.setCharFormat(format);
        }
    }
}

} // namespace db::widgets
