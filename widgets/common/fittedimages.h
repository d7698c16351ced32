#pragma once

#include <QImage>
#include <QObject>

class QTextBrowser;

namespace db::widgets {

// Shows the images of a text browser's document (a manual's screenshots) no wider than its
// viewport, keeping their aspect ratio, so that reading needs no sideways scrolling: again after
// every new document and every resize. Images narrower than the viewport keep their size.
class FittedImages : public QObject
{
    Q_OBJECT
public:
    // Lives as the browser's child.
    static void install(QTextBrowser *browser);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    explicit FittedImages(QTextBrowser *browser);
    void fit();
    QImage imageOf(const QString &name) const;

    QTextBrowser *m_browser;
    int m_width = -1; // the viewport width the images were fitted to
};

} // namespace db::widgets
