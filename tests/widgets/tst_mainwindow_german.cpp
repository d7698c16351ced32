// The main window in German as a user walks through it, with the demo devices connected (the
// MovingCap over RefGo and CANopen, the ACTIVE Cube over VABus): every page, every dock, the menus
// and the dialogs (connect, description library, settings, About). No text on screen is one of
// the program's English texts that has a German translation (a text made before the translation
// was installed, or kept from an English start), and none reads as an English sentence (a text
// that never went through tr()). Device data in tables (names and values the descriptions give)
// is not checked here. With DRIVEBENCH_SCREENSHOT_DIR=DIR it saves each view as
// DIR/de-NAME.png.
#include "common/demodrive.h"
#include "common/protocols.h"
#include "core/connectionhealth.h"
#include "devices/bonfiglioli/acudescription.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "devices/movingcap/movingcapdrive.h"
#include "englishtext.h"
#include "mainwindow.h"
#include "translations/language.h"
#include "widgets/connection/devicelist.h"
#include "widgets/connection/drivestatuspanel.h"
#include "widgets/motion/jogpanel.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocumentFragment>
#include <QTimer>

#include <functional>

using namespace db;
using db::gui::MainWindow;

namespace {

// The English sources of drivebench_de.ts whose German text differs: shown in a German window,
// such a text is a leftover. Texts with placeholders are left out (they never show as written).
QSet<QString> translatedSources()
{
    QFile file(QStringLiteral(DRIVEBENCH_SOURCE_DIR "/translations/drivebench_de.ts"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QString ts = QString::fromUtf8(file.readAll());
    static const QRegularExpression message(
        QStringLiteral("<source>([^<]*)</source>\\s*(?:<comment>[^<]*</"
                       "comment>\\s*)?<translation>([^<]*)</translation>"));
    const auto unescape = [](QString t) {
        return t.replace(QLatin1String("&lt;"), QLatin1String("<"))
            .replace(QLatin1String("&gt;"), QLatin1String(">"))
            .replace(QLatin1String("&quot;"), QLatin1String("\""))
            .replace(QLatin1String("&apos;"), QLatin1String("'"))
            .replace(QLatin1String("&amp;"), QLatin1String("&"));
    };
    QSet<QString> sources;
    QSet<QString> same;
    for (auto it = message.globalMatch(ts); it.hasNext();) {
        const auto m = it.next();
        const QString source = unescape(m.captured(1));
        const QString german = unescape(m.captured(2));
        if (german == source)
            same.insert(source); // kept as it is somewhere ("Reset" of NMT)
        else if (!german.isEmpty() && !source.contains(QLatin1Char('%')) && source.size() > 2)
            sources.insert(source);
    }
    return sources - same;
}

QString plain(const QString &text)
{
    QString t =
        Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText() : text;
    t.remove(QRegularExpression(QStringLiteral("&(?=[^&\\s])")));
    return t.trimmed();
}

// Every text a user reads in `root` and its visible children: labels, buttons, group and tab
// titles, combo box entries, placeholders, tooltips, column headers. `where` names each.
void collect(QWidget *root, const QString &view, QMap<QString, QString> &texts)
{
    QList<QWidget *> widgets = root->findChildren<QWidget *>();
    widgets.prepend(root);
    const auto add = [&](const QString &text, QWidget *w) {
        const QString t = plain(text);
        if (!t.isEmpty())
            texts.insert(
                t,
                QStringLiteral("%1: %2 %3")
                    .arg(view, QLatin1String(w->metaObject()->className()), w->objectName()));
    };
    for (QWidget *w : std::as_const(widgets)) {
        if (!w->isVisibleTo(root) && w != root)
            continue;
        add(w->toolTip(), w);
        if (auto *label = qobject_cast<QLabel *>(w))
            add(label->text(), w);
        else if (auto *button = qobject_cast<QAbstractButton *>(w))
            add(button->text(), w);
        else if (auto *box = qobject_cast<QGroupBox *>(w))
            add(box->title(), w);
        else if (auto *edit = qobject_cast<QLineEdit *>(w))
            add(edit->placeholderText(), w);
        else if (auto *combo = qobject_cast<QComboBox *>(w); combo && !combo->isEditable()) {
            for (int i = 0; i < combo->count(); ++i)
                add(combo->itemText(i), w);
        } else if (auto *tabs = qobject_cast<QTabBar *>(w)) {
            for (int i = 0; i < tabs->count(); ++i) {
                add(tabs->tabText(i), w);
                add(tabs->tabToolTip(i), w);
            }
        } else if (auto *dock = qobject_cast<QDockWidget *>(w)) {
            add(dock->windowTitle(), w);
        } else if (auto *view = qobject_cast<QAbstractItemView *>(w); view && view->model()) {
            for (int c = 0; c < view->model()->columnCount(); ++c) {
                add(view->model()->headerData(c, Qt::Horizontal).toString(), w);
                add(view->model()->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString(), w);
            }
        }
    }
}

void collectMenu(QMenu *menu, const QString &view, QMap<QString, QString> &texts)
{
    for (QAction *action : menu->actions()) {
        const QString t = plain(action->text());
        if (!t.isEmpty())
            texts.insert(t, view + QStringLiteral(": menu ") + plain(menu->title()));
        const QString tip = plain(action->toolTip());
        if (!tip.isEmpty() && tip != t)
            texts.insert(tip, view + QStringLiteral(": menu tooltip"));
        if (action->menu())
            collectMenu(action->menu(), view, texts);
    }
}

void shoot(QWidget *w, const QString &name)
{
    const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
    if (!dir.isEmpty())
        w->grab().save(QStringLiteral("%1/de-%2.png").arg(dir, name));
}

} // namespace

class TestMainWindowGerman : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;

    // Runs `open` (which shows a modal dialog and returns when it closes), collects the dialog's
    // texts and closes it.
    void inDialog(const QString &name, const std::function<void()> &open,
                  QMap<QString, QString> &texts)
    {
        bool seen = false;
        QTimer poll;
        poll.setInterval(50);
        connect(&poll, &QTimer::timeout, this, [&] {
            QWidget *modal = QApplication::activeModalWidget();
            if (!modal || seen)
                return;
            seen = true;
            QTest::qWait(200); // the dialog fills itself
            collect(modal, name, texts);
            shoot(modal, name);
            modal->close();
        });
        poll.start();
        open();
        QVERIFY2(seen, qPrintable(name));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    }

    void cleanup() { i18n::installTranslations(*qApp, QStringLiteral("en")); }

    // Names that files and descriptions use stay what they are in German: the ACTIVE Cube's
    // description (parameter addresses) loads, so the inverter shows its parameters and, when
    // it is not the device on screen, the health check reads one of them and calls it
    // responding (before, its lamp stayed "waiting for an answer").
    void keysStayUntranslated()
    {
        QVERIFY(i18n::installTranslations(*qApp, QStringLiteral("de")));
        QCOMPARE(AddressFormat::parameter().key(), QStringLiteral("parameter"));
        const auto loaded = bonfiglioli::loadAcuDictionary();
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().toString()));
        QCOMPARE(loaded->addressFormat().key(), QStringLiteral("parameter"));

        bonfiglioli::SimulatedAcu acu;
        QVERIFY(acu.listen(0).ok());
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo().ok());
        MainWindow window(app::protocolRegistry());
        window.show();
        auto opened = window.openConnection(QStringLiteral("vabus://127.0.0.1:%1").arg(acu.port()));
        QVERIFY(opened.ok());
        QVERIFY((*opened)->dictionary().contains(ObjectAddress(372, 2)));
        QVERIFY(window.openConnection(demo.refgoUri()).ok()); // now the device on screen
        ConnectionHealth *health = ConnectionHealth::of(*opened);
        QTRY_VERIFY2_WITH_TIMEOUT(health->status() == ConnectionHealth::Status::Responding,
                                  qPrintable(health->description()), 10000);
    }

    void noEnglishLeftOnAnyView()
    {
        const QSet<QString> sources = translatedSources();
        QVERIFY(sources.size() > 1000);
        QVERIFY(i18n::installTranslations(*qApp, QStringLiteral("de")));
        app::DemoDrive demo;
        QVERIFY(demo.startRefgo(0).ok());
        QVERIFY(demo.startSlcan(0).ok());
        bonfiglioli::SimulatedAcu acu;
        QVERIFY(acu.listen(0).ok());

        MainWindow window(app::protocolRegistry());
        window.resize(1366, 740);
        window.show();
        QVERIFY(window.openConnection(QStringLiteral("vabus://127.0.0.1:%1").arg(acu.port())).ok());
        QVERIFY(window.openConnection(demo.slcanUri()).ok());
        QVERIFY(window.openConnection(demo.refgoUri()).ok());
        QTRY_VERIFY_WITH_TIMEOUT(!window.statusPanel()->isStale(ObjectAddress(0x6041, 0)), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(window.jogPanel()->limitsKnown(), 10000);

        QMap<QString, QString> texts; // text -> where it was seen
        for (QDockWidget *dock : window.findChildren<QDockWidget *>()) {
            dock->show();
            collect(dock, dock->objectName(), texts);
        }
        for (QMenu *menu : window.menuBar()->findChildren<QMenu *>(Qt::FindDirectChildrenOnly)) {
            texts.insert(plain(menu->title()), QStringLiteral("menu bar"));
            collectMenu(menu, QStringLiteral("menu bar"), texts);
        }
        // Every page with each kind of device current: the pages change with the device.
        for (DeviceConnection *connection : window.connections()) {
            window.deviceList()->setCurrentConnection(connection);
            QTest::qWait(300);
            for (int i = 0; i < window.pages()->count(); ++i) {
                if (!window.pages()->isTabVisible(i))
                    continue;
                window.pages()->setCurrentIndex(i);
                QTest::qWait(200);
                const QString name = QStringLiteral("%1-%2").arg(
                    connection->uri().scheme(), window.pages()->widget(i)->objectName());
                collect(window.pages()->widget(i), name, texts);
                collect(&window, name, texts);
                shoot(&window, name);
            }
        }
        inDialog(
            QStringLiteral("connect"), [&] { window.showConnectDialog(); }, texts);
        inDialog(
            QStringLiteral("settings"), [&] { window.showSettings(); }, texts);
        inDialog(
            QStringLiteral("about"), [&] { window.showAbout(); }, texts);

        QStringList leftovers;
        for (auto it = texts.cbegin(); it != texts.cend(); ++it) {
            for (const QString &line : it.key().split(QLatin1Char('\n'))) {
                const QString t = line.trimmed();
                if (sources.contains(t))
                    leftovers << QStringLiteral("not translated: '%1' (%2)").arg(t, it.value());
                else if (test::readsAsEnglish(t))
                    leftovers << QStringLiteral("English: '%1' (%2)").arg(t, it.value());
            }
        }
        QVERIFY2(leftovers.isEmpty(), qPrintable(leftovers.join(QLatin1Char('\n'))));
        window.closeAllConnections();
    }
};

QTEST_MAIN(TestMainWindowGerman)
#include "tst_mainwindow_german.moc"
