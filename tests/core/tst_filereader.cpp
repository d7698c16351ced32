// Reading whole files with a size limit, and positions in parse errors; the loaders of
// descriptions, parameter sets and recordings refuse an oversized file by its size.
#include "core/filereader.h"
#include "description/descriptionfile.h"
#include "description/devicedescription.h"
#include "parameters/parameterset.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace db;

class TestFileReader : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    // A sparse file of `bytes` bytes (no disk space used).
    QString bigFile(const QString &name, qint64 bytes)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || !f.resize(bytes))
            return {};
        return path;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void readsAFileWithinTheLimit()
    {
        const QString path = m_dir.filePath(QStringLiteral("small.txt"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("hello\n");
        f.close();
        const auto bytes = files::readAll(path, 6, QStringLiteral("a test file"));
        QVERIFY(bytes.ok());
        QCOMPARE(*bytes, QByteArray("hello\n"));
    }

    void refusesAFileOverTheLimitBySize()
    {
        const QString path = bigFile(QStringLiteral("big.bin"), 3 * files::kMiB);
        QVERIFY(!path.isEmpty());
        const auto bytes = files::readAll(path, 2 * files::kMiB, QStringLiteral("a test file"));
        QVERIFY(!bytes.ok());
        QCOMPARE(bytes.error().kind(), Error::Kind::InvalidArgument);
        const QString m = bytes.error().message();
        QVERIFY2(m.contains(path) && m.contains(QStringLiteral("3.0 MB"))
                     && m.contains(QStringLiteral("2.0 MB"))
                     && m.contains(QStringLiteral("a test file")),
                 qPrintable(m));
    }

    void namesMissingFilesAndFolders()
    {
        const auto missing =
            files::readAll(m_dir.filePath(QStringLiteral("nope")), 10, QStringLiteral("x"));
        QCOMPARE(missing.error().kind(), Error::Kind::Io);
        QVERIFY(missing.error().message().contains(QStringLiteral("nope")));
        const auto folder = files::readAll(m_dir.path(), 10, QStringLiteral("x"));
        QCOMPARE(folder.error().kind(), Error::Kind::Io);
        QVERIFY2(folder.error().message().contains(QStringLiteral("folder")),
                 qPrintable(folder.error().message()));
    }

    void textPositionIsLineAndColumn_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("offset");
        QTest::addColumn<QString>("expected");
        QTest::newRow("start") << QByteArray("abc") << 0 << "line 1, column 1";
        QTest::newRow("first line") << QByteArray("abc") << 2 << "line 1, column 3";
        QTest::newRow("after newline") << QByteArray("ab\ncd") << 3 << "line 2, column 1";
        QTest::newRow("third line") << QByteArray("a\nb\ncde") << 6 << "line 3, column 3";
        QTest::newRow("umlaut counts once")
            << QByteArray("x\n\xc3\xa4z") << 4 << "line 2, column 2";
        QTest::newRow("past the end") << QByteArray("ab") << 99 << "line 1, column 3";
    }

    void textPositionIsLineAndColumn()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, offset);
        QFETCH(QString, expected);
        QCOMPARE(files::textPosition(text, offset), expected);
    }

    void loadersRefuseOversizedFiles()
    {
        const QString set = bigFile(QStringLiteral("huge.dbp"), files::kParameterSetLimit + 1);
        const auto p = ParameterSet::load(set);
        QVERIFY(!p.ok());
        QVERIFY2(p.error().message().contains(QStringLiteral("a parameter set")),
                 qPrintable(p.error().message()));
        const QString eds = bigFile(QStringLiteral("huge.eds"), files::kDescriptionLimit + 1);
        const auto d = loadDeviceDescription(eds);
        QVERIFY(!d.ok());
        QVERIFY2(d.error().message().contains(QStringLiteral("a device description")),
                 qPrintable(d.error().message()));
    }

    void jsonErrorsNameLineAndColumn()
    {
        const auto d = parseJsonDescription("{\n  \"format\": ,\n}", QStringLiteral("x.json"));
        QVERIFY(!d.ok());
        QVERIFY2(d.error().message().contains(QStringLiteral("line 2, column")),
                 qPrintable(d.error().message()));
    }
};

QTEST_GUILESS_MAIN(TestFileReader)
#include "tst_filereader.moc"
