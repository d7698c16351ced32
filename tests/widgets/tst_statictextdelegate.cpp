// The cached-text delegate of the CAN monitor: texts laid out once, elided like the standard
// delegate, drawn with the model's colour and alignment where the standard delegate draws them.
#include "widgets/common/statictextdelegate.h"

#include <QHeaderView>
#include <QImage>
#include <QStandardItemModel>
#include <QTableView>
#include <QTest>

using namespace db::widgets;

namespace {

// The bounding box of the pixels in `rect` that differ clearly from the cell's background.
QRect inkBox(const QImage &image, const QRect &rect, const QColor &background)
{
    QRect box;
    for (int y = rect.top(); y <= rect.bottom(); ++y) {
        for (int x = rect.left(); x <= rect.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            const int d = qAbs(c.red() - background.red()) + qAbs(c.green() - background.green())
                + qAbs(c.blue() - background.blue());
            if (d > 120)
                box |= QRect(x, y, 1, 1);
        }
    }
    return box;
}

bool hasRed(const QImage &image, const QRect &rect)
{
    for (int y = rect.top(); y <= rect.bottom(); ++y)
        for (int x = rect.left(); x <= rect.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.red() > 150 && c.green() < 100 && c.blue() < 100)
                return true;
        }
    return false;
}

} // namespace

class TestStaticTextDelegate : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void textsAreLaidOutOnce();
    void longTextIsElided();
    void drawnWhereTheStandardDelegateDrawsIt();

private:
    QImage render(QAbstractItemDelegate *delegate);
    QStandardItemModel *m_model = nullptr;
    QTableView *m_view = nullptr;
};

void TestStaticTextDelegate::init()
{
    m_model = new QStandardItemModel(3, 2);
    m_model->setItem(0, 0, new QStandardItem(QStringLiteral("TX")));
    auto *right = new QStandardItem(QStringLiteral("12.5"));
    right->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_model->setItem(1, 0, right);
    auto *red = new QStandardItem(QStringLiteral("abort"));
    red->setForeground(QColor(220, 0, 0));
    m_model->setItem(2, 0, red);
    m_model->setItem(0, 1, new QStandardItem(QStringLiteral("upload 603F:0 error code")));
    m_view = new QTableView;
    m_view->setModel(m_model);
    m_view->setShowGrid(false);
    m_view->setWordWrap(false);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->hide();
    m_view->setColumnWidth(0, 120);
    m_view->setColumnWidth(1, 70);
    m_view->resize(260, 120);
}

void TestStaticTextDelegate::cleanup()
{
    delete m_view;
    delete m_model;
}

QImage TestStaticTextDelegate::render(QAbstractItemDelegate *delegate)
{
    m_view->setItemDelegate(delegate);
    return m_view->viewport()->grab().toImage();
}

void TestStaticTextDelegate::textsAreLaidOutOnce()
{
    auto *delegate = new StaticTextDelegate(m_view);
    render(delegate);
    const int laidOut = delegate->cachedTexts();
    QCOMPARE(laidOut, 4);
    m_view->viewport()->grab();
    QCOMPARE(delegate->cachedTexts(), laidOut); // the second paint draws from the cache
    m_model->item(0, 0)->setText(QStringLiteral("RX"));
    m_view->viewport()->grab();
    QCOMPARE(delegate->cachedTexts(), laidOut + 1);
}

void TestStaticTextDelegate::longTextIsElided()
{
    StaticTextDelegate delegate;
    const QFont font = m_view->font();
    const QString text = QStringLiteral("upload 603F:0 error code");
    QCOMPARE(delegate.shownText(QStringLiteral("TX"), font, 60), QStringLiteral("TX"));
    const QString shown = delegate.shownText(text, font, 60);
    QVERIFY2(shown.endsWith(QChar(0x2026)) && shown.size() < text.size(), qPrintable(shown));
    QVERIFY(QFontMetrics(font).horizontalAdvance(shown) <= 60);
}

void TestStaticTextDelegate::drawnWhereTheStandardDelegateDrawsIt()
{
    const QImage standard = render(new QStyledItemDelegate(m_view));
    const QImage cached = render(new StaticTextDelegate(m_view));
    QCOMPARE(cached.size(), standard.size());
    for (int row = 0; row < 3; ++row) {
        const QRect cell = m_view->visualRect(m_model->index(row, 0));
        const QColor background = standard.pixelColor(cell.left() + 1, cell.top() + 1);
        const QRect a = inkBox(standard, cell, background);
        const QRect b = inkBox(cached, cell, background);
        QVERIFY2(!a.isEmpty() && !b.isEmpty(), qPrintable(QString::number(row)));
        const QString where = QStringLiteral("row %1: standard %2,%3 %4x%5, cached %6,%7 %8x%9")
                                  .arg(row)
                                  .arg(a.x())
                                  .arg(a.y())
                                  .arg(a.width())
                                  .arg(a.height())
                                  .arg(b.x())
                                  .arg(b.y())
                                  .arg(b.width())
                                  .arg(b.height());
        QVERIFY2(qAbs(a.left() - b.left()) <= 2 && qAbs(a.right() - b.right()) <= 2
                     && qAbs(a.top() - b.top()) <= 2 && qAbs(a.bottom() - b.bottom()) <= 2,
                 qPrintable(where));
    }
    // The model's colour.
    QVERIFY(hasRed(cached, m_view->visualRect(m_model->index(2, 0))));
    QVERIFY(!hasRed(cached, m_view->visualRect(m_model->index(0, 0))));
}

QTEST_MAIN(TestStaticTextDelegate)
#include "tst_statictextdelegate.moc"
