// Level 1: the description library matches a device's identity (1018h) to our descriptions and
// the files of the user's folder.
#include "description/descriptionlibrary.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace db;

namespace {

QByteArray eds(quint32 vendor, quint32 product, const QString &revision, const QString &name)
{
    QByteArray text = "[FileInfo]\nFileVersion=1\n[DeviceInfo]\nVendorName=Test\n";
    text += "VendorNumber=0x" + QByteArray::number(vendor, 16) + "\n";
    text += "ProductNumber=0x" + QByteArray::number(product, 16) + "\n";
    if (!revision.isEmpty())
        text += "RevisionNumber=" + revision.toLatin1() + "\n";
    text += "ProductName=" + name.toLatin1() + "\n";
    text += "[1000]\nParameterName=Device type\nObjectType=0x7\nDataType=0x0007\n"
            "AccessType=ro\nDefaultValue=0x191\nPDOMapping=0\n";
    text += "[1014]\nParameterName=COB-ID EMCY\nObjectType=0x7\nDataType=0x0007\n"
            "AccessType=rw\nDefaultValue=$NODEID+0x80\nPDOMapping=0\n";
    return text;
}

bool writeFile(const QString &path, const QByteArray &data)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(data) == data.size();
}

LibraryEntry builtin(const QString &name, quint32 vendor, std::optional<quint32> product)
{
    return { name,
             QStringLiteral("built-in"),
             vendor,
             product,
             std::nullopt,
             [name](quint8) -> Result<ObjectDictionary> {
                 ObjectDictionary d;
                 d.identity.productName = name;
                 ObjectDef def;
                 def.address = { 0x1000, 0 };
                 def.name = name;
                 def.type = DataType::Unsigned32;
                 d.insert(def);
                 return d;
             } };
}

} // namespace

class TestDescriptionLibrary : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void productBeatsFamilyAndOtherVendorsNeverMatch()
    {
        DescriptionLibrary library;
        library.addBuiltin(builtin(QStringLiteral("family"), 0xEC, std::nullopt));
        library.addBuiltin(builtin(QStringLiteral("NM172"), 0xEC, 0x71));
        auto m = library.match({ 0xEC, 0x71, 0x00010001 });
        QVERIFY(m);
        QCOMPARE(m->name, QStringLiteral("NM172"));
        m = library.match({ 0xEC, 0x99, std::nullopt });
        QVERIFY(m);
        QCOMPARE(m->name, QStringLiteral("family"));
        QVERIFY(!library.match({ 0x53B, 0x71, std::nullopt }));
    }

    void folderFilesAreMatchedByIdentityAndRevision()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(writeFile(dir.filePath(QStringLiteral("a_rev1.eds")),
                          eds(0x42, 7, QStringLiteral("0x00010000"), QStringLiteral("Rev1"))));
        QVERIFY(writeFile(dir.filePath(QStringLiteral("b_rev2.eds")),
                          eds(0x42, 7, QStringLiteral("0x00020000"), QStringLiteral("Rev2"))));
        QVERIFY(writeFile(dir.filePath(QStringLiteral("c_any.eds")),
                          eds(0x42, 8, QString(), QStringLiteral("Any"))));
        QVERIFY(writeFile(dir.filePath(QStringLiteral("broken.eds")), "not a description\n"));
        QVERIFY(writeFile(dir.filePath(QStringLiteral("notes.txt")), "ignored\n"));
        DescriptionLibrary library;
        library.addBuiltin(builtin(QStringLiteral("ours"), 0x42, 7));
        library.setFolder(dir.path());
        library.rescan();
        library.addBuiltin(builtin(QStringLiteral("ours for 8"), 0x42, 8));
        QCOMPARE(library.entries().size(), 5);
        QCOMPARE(library.warnings().size(), 1);
        QVERIFY2(library.warnings().first().contains(QStringLiteral("broken.eds")),
                 qPrintable(library.warnings().first()));

        auto m = library.match({ 0x42, 7, 0x00020000 });
        QVERIFY(m);
        QCOMPARE(m->name, QStringLiteral("Rev2"));
        // Another revision: a description for every revision fits better than one for
        // another revision.
        m = library.match({ 0x42, 7, 0x00030000 });
        QVERIFY(m);
        QCOMPARE(m->name, QStringLiteral("ours"));
        // Equally good: the user's file wins over ours.
        m = library.match({ 0x42, 8, 0x00030000 });
        QVERIFY(m);
        QCOMPARE(m->name, QStringLiteral("Any"));
        // The entry loads with the node id resolved.
        m = library.match({ 0x42, 7, 0x00010000 });
        QVERIFY(m);
        QCOMPARE(m->name, QStringLiteral("Rev1"));
        const auto dict = m->load(5);
        QVERIFY2(dict.ok(), qPrintable(dict.error().toString()));
        const ObjectDef *emcy = dict->find({ 0x1014, 0 });
        QVERIFY(emcy);
        QCOMPARE(emcy->defaultValue.toULongLong(), 0x85ull);
    }

    void addFileCopiesIntoTheFolder()
    {
        QTemporaryDir source;
        QTemporaryDir folder;
        const QString file = source.filePath(QStringLiteral("device.eds"));
        QVERIFY(writeFile(file, eds(0x77, 1, QString(), QStringLiteral("Added"))));
        DescriptionLibrary library;
        QVERIFY(!library.addFile(file)); // no folder set
        library.setFolder(folder.filePath(QStringLiteral("library")));
        QVERIFY(!library.match({ 0x77, 1, std::nullopt }));
        const auto added = library.addFile(file);
        QVERIFY2(added.ok(), qPrintable(added.error().toString()));
        QVERIFY(QFile::exists(*added));
        const auto m = library.match({ 0x77, 1, std::nullopt });
        QVERIFY(m);
        QCOMPARE(m->origin, *added);

        const QString broken = source.filePath(QStringLiteral("broken.eds"));
        QVERIFY(writeFile(broken, "garbage\n"));
        const auto refused = library.addFile(broken);
        QVERIFY(!refused);
        QVERIFY2(refused.error().message().contains(QStringLiteral("broken.eds")),
                 qPrintable(refused.error().message()));
    }

    void revisionTextAsNumber()
    {
        QCOMPARE(parseRevision(QStringLiteral("0x00010001")), std::optional<quint32>(0x10001));
        QCOMPARE(parseRevision(QStringLiteral("65537")), std::optional<quint32>(65537));
        QVERIFY(!parseRevision(QStringLiteral("1.0")));
        QVERIFY(!parseRevision(QStringLiteral("manual rev. 0")));
    }
};

QTEST_GUILESS_MAIN(TestDescriptionLibrary)
#include "tst_descriptionlibrary.moc"
