// The quiet scroll bar repaints when its picture changes (handle moved or resized, an end
// reached or left) and not for range or value changes that leave the picture as it was; its
// picture is QScrollBar's; a repaint it cannot avoid is a copy and repaints nothing beneath it.
#include "widgets/common/quietscrollbar.h"

#include <QHeaderView>
#include <QStandardItemModel>
#include <QTableView>
#include <QTest>
#include <QVBoxLayout>

using namespace db::widgets;

namespace {

class PaintCounter : public QObject
{
public:
    int paints = 0;
    bool eventFilter(QObject *, QEvent *event) override
    {
        if (event->type() == QEvent::Paint)
            ++paints;
        return false;
    }
};

// Lets pending repaints happen.
void settle()
{
    for (int i = 0; i < 3; ++i) {
        QCoreApplication::processEvents();
        QTest::qWait(10);
    }
}

// Rows for QScrollBar (what the quiet one saves) and QuietScrollBar.
void bothBars()
{
    QTest::addColumn<bool>("quiet");
    QTest::newRow("QScrollBar") << false;
    QTest::newRow("QuietScrollBar") << true;
}

} // namespace

class TestQuietScrollBar : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void growingLogAtTheBottomIsNotRepainted_data();
    void growingLogAtTheBottomIsNotRepainted();
    void changesOfThePictureRepaint();
    void pictureIsQScrollBars();
    void repaintsAreCopies();
    void growingTableRepaintsOnlyItsRows_data();
    void growingTableRepaintsOnlyItsRows();

private:
    // A window with `bar` 300 px tall, shown, with a range whose handle is at its smallest.
    void show(QScrollBar *bar, QWidget &window, PaintCounter &counter);
};

void TestQuietScrollBar::show(QScrollBar *bar, QWidget &window, PaintCounter &counter)
{
    auto *layout = new QVBoxLayout(&window);
    layout->addWidget(bar);
    window.resize(40, 300);
    bar->setRange(0, 100000);
    bar->setPageStep(10);
    bar->setValue(bar->maximum());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    settle();
    bar->installEventFilter(&counter);
}

void TestQuietScrollBar::growingLogAtTheBottomIsNotRepainted_data()
{
    bothBars();
}

void TestQuietScrollBar::growingLogAtTheBottomIsNotRepainted()
{
    QFETCH(bool, quiet);
    QWidget window;
    PaintCounter counter;
    QScrollBar *bar = quiet ? new QuietScrollBar(Qt::Vertical) : new QScrollBar(Qt::Vertical);
    show(bar, window, counter);
    if (QTest::currentTestFailed())
        return;
    for (int rows = 1; rows <= 10; ++rows) {
        bar->setMaximum(100000 + 18 * rows); // a batch of 18 rows, then follow the last one
        bar->setValue(bar->maximum());
        settle();
    }
    if (quiet)
        QCOMPARE(counter.paints, 0);
    else
        QVERIFY2(counter.paints >= 10, qPrintable(QString::number(counter.paints))); // the cost
}

void TestQuietScrollBar::changesOfThePictureRepaint()
{
    QWidget window;
    PaintCounter counter;
    auto *bar = new QuietScrollBar(Qt::Vertical);
    show(bar, window, counter);
    if (QTest::currentTestFailed())
        return;

    bar->setValue(50000); // the handle moves to the middle
    settle();
    QCOMPARE(counter.paints, 1);

    bar->setValue(50001); // less than a pixel: the same picture
    settle();
    QCOMPARE(counter.paints, 1);

    bar->setValue(0); // at the top
    settle();
    QCOMPARE(counter.paints, 2);
    bar->setValue(1); // leaves the end without moving a pixel: the arrow is enabled again
    settle();
    QCOMPARE(counter.paints, 3);

    bar->setRange(0, 10); // the handle grows to half the groove
    settle();
    QCOMPARE(counter.paints, 4);

    bar->setRange(0, 0); // nothing to scroll
    settle();
    QCOMPARE(counter.paints, 5);

    window.resize(40, 200); // a resize repaints as usual
    settle();
    QVERIFY(counter.paints >= 6);
}

void TestQuietScrollBar::pictureIsQScrollBars()
{
    QWidget plainWindow, quietWindow;
    PaintCounter plainCounter, quietCounter;
    auto *plain = new QScrollBar(Qt::Vertical);
    auto *quiet = new QuietScrollBar(Qt::Vertical);
    show(plain, plainWindow, plainCounter);
    show(quiet, quietWindow, quietCounter);
    if (QTest::currentTestFailed())
        return;
    const QList<std::pair<int, int>> cases {
        { 100000, 100000 }, { 100000, 0 }, { 100000, 50000 }, { 10, 3 }, { 0, 0 }
    };
    for (const auto &[maximum, value] : cases) {
        for (QScrollBar *bar : { plain, static_cast<QScrollBar *>(quiet) }) {
            bar->setRange(0, maximum);
            bar->setValue(value);
        }
        settle();
        const QImage a = plain->grab().toImage().convertToFormat(QImage::Format_RGB32);
        const QImage b = quiet->grab().toImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY2(!a.isNull() && a == b,
                 qPrintable(QStringLiteral("maximum %1, value %2").arg(maximum).arg(value)));
    }
}

void TestQuietScrollBar::repaintsAreCopies()
{
    QWidget window;
    PaintCounter counter;
    auto *bar = new QuietScrollBar(Qt::Vertical);
    show(bar, window, counter);
    if (QTest::currentTestFailed())
        return;
    const int drawn = bar->drawnPictures();
    QVERIFY(drawn >= 1);
    for (int i = 0; i < 5; ++i) {
        bar->update();
        settle();
    }
    QCOMPARE(counter.paints, 5);
    QCOMPARE(bar->drawnPictures(), drawn);
    bar->setValue(0);
    settle();
    QCOMPARE(bar->drawnPictures(), drawn + 1);
}

void TestQuietScrollBar::growingTableRepaintsOnlyItsRows_data()
{
    bothBars();
}

// A log table wider and longer than its view (both scroll bars shown) that follows its last
// row: only the rows are painted again, not its frame; the scroll bars are copied.
void TestQuietScrollBar::growingTableRepaintsOnlyItsRows()
{
    QFETCH(bool, quiet);
    QStandardItemModel model(0, 6);
    const auto addRows = [&model](int n) {
        for (int i = 0; i < n; ++i) {
            QList<QStandardItem *> row;
            for (int c = 0; c < 6; ++c)
                row << new QStandardItem(
                    QStringLiteral("row %1 column %2 with some text").arg(model.rowCount()).arg(c));
            model.appendRow(row);
        }
    };
    addRows(500);
    QTableView view;
    view.setModel(&model);
    view.verticalHeader()->hide();
    view.horizontalHeader()->setDefaultSectionSize(200);
    if (quiet)
        QuietScrollBar::install(&view);
    view.resize(400, 200);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.scrollToBottom();
    settle();
    QVERIFY(view.verticalScrollBar()->isVisible());
    QVERIFY(view.horizontalScrollBar()->isVisible());
    PaintCounter frame, vertical, horizontal;
    view.installEventFilter(&frame);
    view.verticalScrollBar()->installEventFilter(&vertical);
    view.horizontalScrollBar()->installEventFilter(&horizontal);
    const auto drawn = [&view] {
        auto *v = qobject_cast<QuietScrollBar *>(view.verticalScrollBar());
        auto *h = qobject_cast<QuietScrollBar *>(view.horizontalScrollBar());
        return v && h ? v->drawnPictures() + h->drawnPictures() : -1;
    };
    const int drawnBefore = drawn();
    for (int batch = 0; batch < 5; ++batch) {
        addRows(18);
        view.scrollToBottom();
        settle();
    }
    QCOMPARE(view.verticalScrollBar()->value(), view.verticalScrollBar()->maximum());
    if (quiet) {
        // The view raises both bars on every relayout, which repaints them; they are copies.
        QCOMPARE(frame.paints, 0);
        QVERIFY(drawnBefore > 0);
        QCOMPARE(drawn(), drawnBefore);
    } else {
        // What this saves: Qt repaints both bars and the frame under them each time.
        QVERIFY(frame.paints >= 5);
        QVERIFY(vertical.paints >= 5);
        QVERIFY(horizontal.paints >= 5);
    }
}

QTEST_MAIN(TestQuietScrollBar)
#include "tst_quietscrollbar.moc"
