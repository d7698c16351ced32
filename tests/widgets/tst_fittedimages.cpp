// The manual's screenshots are shown no wider than the window: no sideways scrolling to read.
#include "widgets/common/fittedimages.h"

#include <QImage>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>

using namespace db::widgets;

class TestFittedImages : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QUrl m_source;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QImage shot(1366, 768, QImage::Format_RGB32);
        shot.fill(Qt::darkCyan);
        QVERIFY(shot.save(m_dir.filePath(QStringLiteral("shot.png"))));
        QImage small(100, 50, QImage::Format_RGB32);
        small.fill(Qt::red);
        QVERIFY(small.save(m_dir.filePath(QStringLiteral("small.png"))));
        QFile md(m_dir.filePath(QStringLiteral("manual.md")));
        QVERIFY(md.open(QIODevice::WriteOnly));
        md.write("# Manual\n\nText before.\n\n![the window](shot.png)\n\n![small](small.png)\n\n"
                 "Text after.\n");
        md.close();
        m_source = QUrl::fromLocalFile(md.fileName());
    }

    void wideScreenshotsFitTheWindow_data()
    {
        QTest::addColumn<bool>("fitted");
        QTest::newRow("as they are") << false;
        QTest::newRow("fitted") << true;
    }
    void wideScreenshotsFitTheWindow()
    {
        QFETCH(bool, fitted);
        QTextBrowser browser;
        browser.resize(600, 400);
        if (fitted)
            FittedImages::install(&browser);
        browser.setSource(m_source, QTextDocument::MarkdownResource);
        browser.show();
        QVERIFY(QTest::qWaitForWindowExposed(&browser));
        QVERIFY(browser.toPlainText().contains(QLatin1String("Text after")));
        if (!fitted) {
            // The control: a 1366 px screenshot makes a 600 px browser scroll sideways.
            QTRY_VERIFY(browser.horizontalScrollBar()->maximum() > 0);
            return;
        }
        QTRY_COMPARE(browser.horizontalScrollBar()->maximum(), 0);
        // Narrower and wider: it follows the window.
        browser.resize(400, 400);
        QTRY_COMPARE(browser.horizontalScrollBar()->maximum(), 0);
        browser.resize(900, 400);
        QTRY_COMPARE(browser.horizontalScrollBar()->maximum(), 0);
    }
};

QTEST_MAIN(TestFittedImages)
#include "tst_fittedimages.moc"
