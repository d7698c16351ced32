// The main window's title names the current connection and its state, and marks ("*") a
// connection that was written to since it last stored its parameters permanently; the standard
// keys: Ctrl+O connect, Ctrl+S store permanently, F5 re-read the objects, Ctrl+F filter them,
// F1 the user manual.
#include "fakeconnection.h"
#include "mainwindow.h"
#include "resources/builtindescriptions.h"
#include "textlanguage.h"
#include "widgets/connection/devicelist.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/parameters/parametersetactions.h"

#include <QAction>
#include <QLineEdit>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTimer>

using namespace db;
using db::gui::MainWindow;
using db::test::FakeConnection;

namespace {

// A fake drive that can store its parameters permanently (1010h "save").
class StoringConnection : public FakeConnection
{
public:
    using FakeConnection::FakeConnection;
    Capabilities capabilities() const override { return Capability::StoreNonVolatile; }
    Reply *storeNonVolatile() override
    {
        ++stores;
        auto *reply = new Reply(ObjectAddress { 0x1010, 1 });
        QTimer::singleShot(0, reply, [reply] { reply->finish(); });
        return reply;
    }
    int stores = 0;
};

ProtocolRegistry fakeRegistry()
{
    ProtocolRegistry registry;
    registry.add({ QStringLiteral("fake"),
                   QStringLiteral("fake"),
                   QStringLiteral("Test double"),
                   QStringLiteral("fake://NAME"),
                   -1,
                   [](const ConnectionPlan &plan) -> Result<std::unique_ptr<DeviceConnection>> {
                       auto fake = std::make_unique<StoringConnection>(plan.uri.toString());
                       fake->setDictionary(resources::movingCapDictionary());
                       fake->setValue({ 0x6041, 0 }, QVariant::fromValue<qulonglong>(0x0427));
                       return std::unique_ptr<DeviceConnection>(std::move(fake));
                   },
                   {},
                   {} });
    return registry;
}

QAction *actionNamed(QWidget &window, const QString &name)
{
    for (QAction *a : window.findChildren<QAction *>()) {
        if (a->objectName() == name)
            return a;
    }
    return nullptr;
}

} // namespace

class TestMainWindowTitle : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    const ProtocolRegistry m_registry = fakeRegistry();

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    }

    void titleNamesConnectionAndUnstoredWrites()
    {
        MainWindow window(m_registry);
        QCOMPARE(window.windowTitle(), QStringLiteral("drivebench"));
        QVERIFY(!window.isWindowModified());

        auto opened = window.openConnection(QStringLiteral("fake://a"));
        QVERIFY(opened);
        auto *a = static_cast<StoringConnection *>(*opened);
        QTRY_COMPARE(window.windowTitle(), QStringLiteral("fake://a (connected)[*]"));
        QVERIFY(!window.isWindowModified());

        // A failed write changes nothing on the device: no mark.
        a->setFailure({ 0x6083, 0 }, Error(Error::Kind::DeviceError, QStringLiteral("refused")));
        std::unique_ptr<Reply> refused(
            a->write({ 0x6083, 0 }, QVariant::fromValue<qulonglong>(2000)));
        QTRY_VERIFY(refused->isFinished());
        QCoreApplication::processEvents();
        QVERIFY(!window.isWindowModified());
        a->clearFailure({ 0x6083, 0 });

        std::unique_ptr<Reply> written(
            a->write({ 0x6083, 0 }, QVariant::fromValue<qulonglong>(2000)));
        QTRY_VERIFY(window.isWindowModified());
        QVERIFY(written->ok());
        QVERIFY(window.hasUnstoredWrites(a));

        // Another connection becomes current: its own state, no mark; back to a: marked again.
        auto other = window.openConnection(QStringLiteral("fake://b"));
        QVERIFY(other);
        QTRY_COMPARE(window.windowTitle(), QStringLiteral("fake://b (connected)[*]"));
        QVERIFY(!window.isWindowModified());
        window.deviceList()->setCurrentConnection(a);
        QTRY_COMPARE(window.windowTitle(), QStringLiteral("fake://a (connected)[*]"));
        QVERIFY(window.isWindowModified());

        // Storing permanently clears the mark of the stored connection.
        window.parameterActions()->storeNow();
        QTRY_COMPARE(a->stores, 1);
        QTRY_VERIFY(!window.hasUnstoredWrites(a));
        QVERIFY(!window.isWindowModified());
    }

    void standardShortcuts()
    {
        MainWindow window(m_registry);
        QAction *store = window.parameterActions()->storeAction();
        QCOMPARE(store->shortcut(), QKeySequence(QKeySequence::Save));
        QAction *refresh = actionNamed(window, QStringLiteral("refreshAction"));
        QAction *filter = actionNamed(window, QStringLiteral("filterAction"));
        QVERIFY(refresh);
        QVERIFY(filter);
        QCOMPARE(refresh->shortcut(), QKeySequence(QKeySequence::Refresh));
        QCOMPARE(filter->shortcut(), QKeySequence(QKeySequence::Find));
        bool open = false;
        for (QAction *a : window.findChildren<QAction *>())
            open = open || a->shortcut() == QKeySequence(QKeySequence::Open);
        QVERIFY(open);

        auto opened = window.openConnection(QStringLiteral("fake://a"));
        QVERIFY(opened);
        auto *a = static_cast<StoringConnection *>(*opened);
        QTRY_VERIFY(a->isConnected());
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));

        // F5: the Object Dictionary page comes to the front and reads the device.
        const int readsBefore = a->readCount;
        refresh->trigger();
        QCOMPARE(window.pages()->currentWidget(), window.odEditor());
        QTRY_VERIFY(a->readCount > readsBefore + 10);

        // Ctrl+F: the filter field gets the focus.
        window.pages()->setCurrentIndex(0);
        filter->trigger();
        QCOMPARE(window.pages()->currentWidget(), window.odEditor());
        auto *edit = window.odEditor()->findChild<QLineEdit *>(QStringLiteral("filter"));
        QVERIFY(edit);
        QTRY_VERIFY(edit->hasFocus());

        // F1: the user manual (the README's part for users) in a window of its own: the file
        // beside the program where it is installed (tst_packaging checks that tree), else the
        // copy built in, as here in the test's folder.
        QAction *manual = actionNamed(window, QStringLiteral("manualAction"));
        QVERIFY(manual);
        QCOMPARE(manual->shortcut(), QKeySequence(QKeySequence::HelpContents));
        QTest::keyClick(&window, Qt::Key_F1);
        auto *text = window.findChild<QTextBrowser *>(QStringLiteral("manualText"));
        QVERIFY(text);
        QTRY_VERIFY(text->isVisible());
        QVERIFY2(text->toPlainText().contains(QStringLiteral("Reaching a real drive")),
                 qPrintable(text->toPlainText().left(200)));
        QVERIFY(!text->toPlainText().contains(QStringLiteral("How the code is organised")));
        QVERIFY(!text->toPlainText().contains(QStringLiteral("How it works")));
        QCOMPARE(text->source().fileName(), QStringLiteral("manual.en.md"));
        QCOMPARE(MainWindow::manualPath().section(QLatin1Char('/'), -1),
                 QStringLiteral("manual.en.md"));
    }

    // In German the manual is the German one.
    void germanManual()
    {
        const test::TextLanguage german(QStringLiteral("de"));
        MainWindow window(m_registry);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTest::keyClick(&window, Qt::Key_F1);
        auto *text = window.findChild<QTextBrowser *>(QStringLiteral("manualText"));
        QVERIFY(text);
        QTRY_VERIFY(text->isVisible());
        QCOMPARE(text->source().fileName(), QStringLiteral("manual.de.md"));
        QVERIFY2(text->toPlainText().contains(QStringLiteral("Einen echten Antrieb erreichen")),
                 qPrintable(text->toPlainText().left(200)));
    }
};

QTEST_MAIN(TestMainWindowTitle)
#include "tst_mainwindow_title.moc"
