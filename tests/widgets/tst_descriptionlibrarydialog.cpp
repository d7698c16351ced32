// The description library dialog: the built-ins and the folder's files with the identity each
// is matched by; a description file dropped onto it (or added with Add…) is checked, copied into
// the folder and listed; a file that does not load is named with its problem and not added.
#include "widgets/odeditor/descriptionlibrarydialog.h"

#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QMimeData>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUrl>

using namespace db;
using db::widgets::DescriptionLibraryDialog;

namespace {
// Drags one file over the dialog and drops it when the drag was accepted.
bool dropFile(QWidget &target, const QString &path)
{
    QMimeData data;
    data.setUrls({ QUrl::fromLocalFile(path) });
    const QPoint at = target.rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&target, &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent drop(QPointF(at), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&target, &drop);
    return drop.isAccepted();
}

QStringList column(const QTreeWidget *list, int c)
{
    QStringList texts;
    for (int i = 0; i < list->topLevelItemCount(); ++i)
        texts.append(list->topLevelItem(i)->text(c));
    return texts;
}
} // namespace

class TestDescriptionLibraryDialog : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void droppedFileJoinsTheLibrary()
    {
        QTemporaryDir folder;
        QTemporaryDir elsewhere;
        QVERIFY(folder.isValid() && elsewhere.isValid());
        DescriptionLibrary library;
        library.addBuiltin(
            { QStringLiteral("NM172"), QStringLiteral("built-in"), 0xEC, 0x71, std::nullopt, {} });
        library.setFolder(folder.path());
        library.rescan();
        DescriptionLibraryDialog dialog(library);
        dialog.show();
        QTreeWidget *list = dialog.list();
        QCOMPARE(column(list, 0), QStringList { QStringLiteral("NM172") });
        QCOMPARE(column(list, 4), QStringList { QStringLiteral("built-in") });

        const QString source = elsewhere.filePath(QStringLiteral("testnode.json"));
        QVERIFY(QFile::copy(
            QStringLiteral(DRIVEBENCH_SOURCE_DIR "/resources/devices/drivebench_testnode.json"),
            source));
        QSignalSpy added(&dialog, &DescriptionLibraryDialog::fileAdded);
        QVERIFY(dropFile(dialog, source));
        QCOMPARE(added.size(), 1);
        const QString copy = QDir(folder.path()).absoluteFilePath(QStringLiteral("testnode.json"));
        QCOMPARE(added.first().first().toString(), copy);
        QVERIFY(QFile::exists(copy));
        QCOMPARE(list->topLevelItemCount(), 2);
        QVERIFY(column(list, 4).contains(QStringLiteral("testnode.json")));
        QVERIFY(column(list, 1).contains(QStringLiteral("00000DB0h")));
        QVERIFY2(dialog.status().contains(QStringLiteral("added")), qPrintable(dialog.status()));

        // A file that does not load is named and not added.
        const QString broken = elsewhere.filePath(QStringLiteral("broken.eds"));
        {
            QFile f(broken);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("[DeviceInfo]\nVendorNumber=banana\n");
        }
        QVERIFY(dropFile(dialog, broken));
        QCOMPARE(added.size(), 1);
        QVERIFY2(dialog.status().contains(QStringLiteral("broken.eds not added")),
                 qPrintable(dialog.status()));
        QVERIFY(!QFile::exists(QDir(folder.path()).absoluteFilePath(QStringLiteral("broken.eds"))));
        QCOMPARE(list->topLevelItemCount(), 2);

        // Not a description file: refused when dragged.
        QVERIFY(!dropFile(dialog, elsewhere.filePath(QStringLiteral("notes.txt"))));
    }
};

QTEST_MAIN(TestDescriptionLibraryDialog)
#include "tst_descriptionlibrarydialog.moc"
