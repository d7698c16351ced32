// The wheel over an unfocused spin box or combo box scrolls the panel and leaves the value alone;
// once the box has the focus, the wheel changes it as usual.
#include "widgets/common/wheelguard.h"

#include <QApplication>
#include <QComboBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QTest>
#include <QVBoxLayout>
#include <QWheelEvent>

using db::widgets::WheelGuard;

namespace {
void turnWheel(QWidget *widget, int notches)
{
    const QPointF pos(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent event(pos, widget->mapToGlobal(pos), QPoint(), QPoint(0, 120 * notches),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &event);
}
} // namespace

class TestWheelGuard : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { WheelGuard::install(); }

    void unfocusedBoxesScrollThePanel()
    {
        QWidget window;
        auto *scroll = new QScrollArea(&window);
        auto *panel = new QWidget;
        auto *layout = new QVBoxLayout(panel);
        auto *other = new QSpinBox(panel); // holds the focus
        auto *spin = new QSpinBox(panel);
        spin->setRange(0, 1000);
        spin->setValue(500);
        auto *combo = new QComboBox(panel);
        combo->addItems({ QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c") });
        combo->setCurrentIndex(1);
        layout->addWidget(other);
        layout->addWidget(spin);
        layout->addWidget(combo);
        layout->addSpacing(2000); // the panel scrolls
        scroll->setWidget(panel);
        (new QVBoxLayout(&window))->addWidget(scroll);
        window.resize(300, 200);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QApplication::setActiveWindow(&window);
        other->setFocus();
        QTRY_VERIFY(other->hasFocus());
        QCOMPARE(spin->focusPolicy(), Qt::StrongFocus); // the wheel does not focus it

        turnWheel(spin, -2);
        turnWheel(combo, -1);
        QCOMPARE(spin->value(), 500);
        QCOMPARE(combo->currentIndex(), 1);
        QVERIFY(scroll->verticalScrollBar()->value() > 0); // the panel scrolled instead

        spin->setFocus();
        QTRY_VERIFY(spin->hasFocus());
        turnWheel(spin, 1);
        QCOMPARE(spin->value(), 501);
        combo->setFocus();
        QTRY_VERIFY(combo->hasFocus());
        turnWheel(combo, -1);
        QCOMPARE(combo->currentIndex(), 2);
    }
};

QTEST_MAIN(TestWheelGuard)
#include "tst_wheelguard.moc"
