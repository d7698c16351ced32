// Long tooltips wrap: a widget's long plain-text tooltip and the editor's object descriptions are
// shown as rich text, which Qt wraps at a readable width instead of one screen-wide line.
#include "widgets/common/tooltipwrapper.h"
#include "widgets/common/widgetstyle.h"
#include "widgets/odeditor/odeditormodel.h"

#include <QApplication>
#include <QHelpEvent>
#include <QLabel>
#include <QPushButton>
#include <QTest>
#include <QTextDocument>
#include <QToolTip>

using namespace db;
using db::widgets::ToolTipWrapper;

namespace {
QString longText()
{
    QStringList words;
    for (int i = 0; i < 60; ++i)
        words << QStringLiteral("word%1").arg(i);
    return words.join(QLatin1Char(' ')) + QStringLiteral(" <not a tag> & more");
}

QLabel *tipLabel()
{
    for (QWidget *w : QApplication::topLevelWidgets()) {
        if (w->objectName() == QLatin1String("qtooltip_label") && w->isVisible())
            return qobject_cast<QLabel *>(w);
    }
    return nullptr;
}

void askForToolTip(QWidget *widget)
{
    const QPoint pos(5, 5);
    QHelpEvent help(QEvent::ToolTip, pos, widget->mapToGlobal(pos));
    QApplication::sendEvent(widget, &help);
}
} // namespace

class TestToolTipWrapper : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { ToolTipWrapper::install(); }

    void longPlainToolTipWraps()
    {
        QPushButton button(QStringLiteral("x"));
        button.setToolTip(longText());
        button.show();
        QVERIFY(QTest::qWaitForWindowExposed(&button));
        askForToolTip(&button);
        QTRY_VERIFY(tipLabel());
        QLabel *label = tipLabel();
        QVERIFY(label->wordWrap());
        QVERIFY(Qt::mightBeRichText(QToolTip::text()));
        QVERIFY(QToolTip::text().contains(QStringLiteral("&lt;not a tag&gt; &amp; more")));
        // Several lines, not one line as wide as the text.
        const int oneLine = label->fontMetrics().horizontalAdvance(longText());
        QVERIFY2(label->width() < oneLine / 2,
                 qPrintable(QStringLiteral("%1 vs %2").arg(label->width()).arg(oneLine)));
        QToolTip::hideText();
    }

    void shortToolTipIsLeftAlone()
    {
        QPushButton button(QStringLiteral("x"));
        button.setToolTip(QStringLiteral("Connect"));
        button.show();
        QVERIFY(QTest::qWaitForWindowExposed(&button));
        askForToolTip(&button);
        QTRY_VERIFY(tipLabel());
        QCOMPARE(QToolTip::text(), QStringLiteral("Connect"));
        QToolTip::hideText();
    }

    void editorDescriptionsAreRichText()
    {
        ObjectDictionary dict;
        ObjectDef def;
        def.address = ObjectAddress(0x6083, 0);
        def.name = QStringLiteral("Profile acceleration");
        def.type = DataType::Unsigned32;
        def.description = longText();
        dict.insert(def);
        widgets::OdEditorModel model;
        model.setDictionary(dict);
        const QModelIndex name = model.indexOf(def.address, widgets::OdEditorModel::Name);
        QVERIFY(name.isValid());
        const QString tip = name.data(Qt::ToolTipRole).toString();
        QVERIFY(Qt::mightBeRichText(tip));
        QCOMPARE(tip, widgets::style::toolTip(longText()));
        QVERIFY(widgets::style::toolTip(QString()).isEmpty());
    }
};

QTEST_MAIN(TestToolTipWrapper)
#include "tst_tooltipwrapper.moc"
