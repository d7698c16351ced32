// The editor's "no description" bar takes a description file dropped onto it, like Browse…:
// one local file with a description suffix; anything else is refused at drag time.
#include "widgets/odeditor/descriptionprompt.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMimeData>
#include <QSignalSpy>
#include <QTest>
#include <QUrl>

using namespace db;
using db::widgets::DescriptionPrompt;

namespace {
std::unique_ptr<QMimeData> urls(const QStringList &paths)
{
    auto data = std::make_unique<QMimeData>();
    QList<QUrl> list;
    for (const QString &path : paths)
        list.append(path.contains(QStringLiteral("://")) ? QUrl(path) : QUrl::fromLocalFile(path));
    data->setUrls(list);
    return data;
}

// Drags `data` over the prompt and drops it when the drag was accepted; true when accepted.
bool dragAndDrop(DescriptionPrompt &prompt, const QMimeData *data)
{
    const QPoint at = prompt.rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, data, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&prompt, &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent drop(QPointF(at), Qt::CopyAction, data, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&prompt, &drop);
    return drop.isAccepted();
}
} // namespace

class TestDescriptionPrompt : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void droppedDescriptionFileIsChosen()
    {
        DescriptionPrompt prompt;
        prompt.resize(400, 60);
        prompt.show();
        QVERIFY(prompt.acceptDrops());
        QSignalSpy chosen(&prompt, &DescriptionPrompt::fileChosen);
        const auto data = urls({ QStringLiteral("/data/Drive X.EDS") });
        QVERIFY(dragAndDrop(prompt, data.get()));
        QCOMPARE(chosen.size(), 1);
        QCOMPARE(chosen.first().first().toString(), QStringLiteral("/data/Drive X.EDS"));
    }

    void otherDropsAreRefused_data()
    {
        QTest::addColumn<QStringList>("paths");
        QTest::newRow("not a description") << QStringList { QStringLiteral("/data/notes.txt") };
        QTest::newRow("two files")
            << QStringList { QStringLiteral("/data/a.eds"), QStringLiteral("/data/b.eds") };
        QTest::newRow("not local") << QStringList { QStringLiteral("https://example.com/a.eds") };
    }

    void otherDropsAreRefused()
    {
        QFETCH(QStringList, paths);
        DescriptionPrompt prompt;
        prompt.show();
        QSignalSpy chosen(&prompt, &DescriptionPrompt::fileChosen);
        const auto data = urls(paths);
        QVERIFY(!dragAndDrop(prompt, data.get()));
        QCOMPARE(chosen.size(), 0);
    }
};

QTEST_MAIN(TestDescriptionPrompt)
#include "tst_descriptionprompt.moc"
