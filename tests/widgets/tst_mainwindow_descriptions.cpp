// Level 4: the main window connects to a simulated CANopen node without ?eds=. The connection
// reads the node's identity (1018h) and takes the matching description from the library
// folder ($DRIVEBENCH_DESCRIPTIONS): the editor lists its objects. Without a match the editor
// shows the prompt with Browse… instead of an empty table. In neither case does any panel poll an
// object the description lacks: the node answers no SDO with an abort.
#include "canopen/canopenconnection.h"
#include "common/protocols.h"
#include "common/simnodes.h"
#include "mainwindow.h"
#include "transport/canbus.h"
#include "widgets/connection/drivestatuspanel.h"
#include "widgets/odeditor/descriptionprompt.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/odeditor/odeditormodel.h"

#include <QCanBusFrame>
#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace db;
using db::gui::MainWindow;

namespace {
constexpr int kRounds = 3; // status panel rounds watched for aborts
}

class TestMainWindowDescriptions : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    QTemporaryDir m_library;

    // Opens node 3 of a fresh simulated bus in a fresh window; counts the SDO aborts the node
    // sends until the status panel has gone through kRounds rounds.
    struct Run
    {
        app::SimNodes nodes;
        std::unique_ptr<MainWindow> window;
        DeviceConnection *connection = nullptr;
        int aborts = 0;
        QStringList abortText;
    };

    void start(Run &run)
    {
        QVERIFY(run.nodes.create({ { 3 }, {}, {} }).ok());
        QVERIFY(run.nodes.startSlcan(0).ok());
        run.window = std::make_unique<MainWindow>(app::protocolRegistry());
        run.window->resize(1366, 768);
        run.window->show();
        const auto opened = run.window->openConnection(
            QStringLiteral("canopen+slcan://127.0.0.1:%1?node=3").arg(run.nodes.slcanPort()));
        QVERIFY2(opened.ok(), qPrintable(opened.error().toString()));
        run.connection = opened.value();
        auto *canopen = qobject_cast<canopen::CanopenConnection *>(run.connection);
        QVERIFY(canopen);
        connect(canopen->bus(), &CanBus::frameReceived, this, [&run](const QCanBusFrame &f) {
            if (f.frameId() == 0x583 && !f.payload().isEmpty() && quint8(f.payload()[0]) == 0x80) {
                ++run.aborts;
                run.abortText.append(QString::fromLatin1(f.payload().toHex(' ')));
            }
        });
        QTRY_VERIFY_WITH_TIMEOUT(run.connection->isConnected(), 5000);
    }

    void watchRounds(Run &run)
    {
        widgets::DriveStatusPanel *panel = run.window->statusPanel();
        QVERIFY(panel->isVisible());
        QSignalSpy rounds(panel, &widgets::DriveStatusPanel::cycleFinished);
        QTRY_VERIFY_WITH_TIMEOUT(rounds.size() >= kRounds, 15000);
        QVERIFY2(run.aborts == 0,
                 qPrintable(QStringLiteral("%1 SDO aborts, first: %2")
                                .arg(run.aborts)
                                .arg(run.abortText.value(0))));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QVERIFY(m_library.isValid());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
        qputenv("DRIVEBENCH_DESCRIPTIONS", m_library.path().toLocal8Bit());
    }

    void matchingDescriptionFromTheLibrary()
    {
        const QString copy = m_library.filePath(QStringLiteral("testnode.json"));
        QFile::remove(copy);
        QVERIFY(QFile::copy(
            QStringLiteral(DRIVEBENCH_SOURCE_DIR "/resources/devices/drivebench_testnode.json"),
            copy));
        Run run;
        start(run);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(run.connection->dictionary().contains(ObjectAddress(0x1008, 0)));
        widgets::OdEditor *editor = run.window->odEditor();
        QTRY_VERIFY(editor->model()->dictionary().contains(ObjectAddress(0x1008, 0)));
        QCOMPARE(editor->model()->dictionary().identity.descriptionFile, copy);
        QVERIFY(!editor->descriptionPrompt()->isVisibleTo(editor));
        watchRounds(run);
        QFile::remove(copy);
    }

    void noMatchShowsThePromptAndPollsNothing()
    {
        Run run;
        start(run);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(run.connection->dictionary().isEmpty());
        QCOMPARE(run.connection->dictionary().identity.vendorId, 0xDB0u);
        widgets::OdEditor *editor = run.window->odEditor();
        widgets::DescriptionPrompt *prompt = editor->descriptionPrompt();
        QVERIFY(prompt->isVisibleTo(editor));
        QVERIFY2(prompt->text().contains(QStringLiteral("00000DB0h")), qPrintable(prompt->text()));
        watchRounds(run);
        if (const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR"); !dir.isEmpty()) {
            for (QTabWidget *tabs : run.window->findChildren<QTabWidget *>()) {
                for (int i = 0; i < tabs->count(); ++i) {
                    if (tabs->widget(i) == editor || tabs->widget(i)->isAncestorOf(editor))
                        tabs->setCurrentIndex(i);
                }
            }
            QTRY_VERIFY(prompt->isVisible());
            run.window->grab().save(dir + QStringLiteral("/screenshot-description-prompt.png"));
        }

        // Browse… ends in useDescriptionFile(): the editor lists the objects, the prompt goes.
        QVERIFY(!editor->useDescriptionFile(m_library.filePath(QStringLiteral("missing.eds"))));
        QVERIFY2(prompt->text().contains(QStringLiteral("missing.eds")),
                 qPrintable(prompt->text()));
        QSignalSpy used(editor, &widgets::OdEditor::descriptionFileUsed);
        QVERIFY(editor->useDescriptionFile(
            QStringLiteral(DRIVEBENCH_SOURCE_DIR "/resources/devices/drivebench_testnode.json")));
        QCOMPARE(used.size(), 1);
        QVERIFY(editor->model()->dictionary().contains(ObjectAddress(0x1008, 0)));
        QVERIFY(!prompt->isVisibleTo(editor));
    }
};

QTEST_MAIN(TestMainWindowDescriptions)
#include "tst_mainwindow_descriptions.moc"
