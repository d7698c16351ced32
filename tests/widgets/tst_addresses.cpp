// The widgets show, take and drag addresses as the connection writes them: for an inverter
// whose parameters are decimal NUMBER:DATASET the editor shows "372:2" (not 0174:2), the
// Read/Write box reads parameter 372 data set 2 for "372:2", the scope takes "372:2", and the
// parameter comparison shows the set's format.
#include "fakeconnection.h"
#include "parameters/parameterset.h"
#include "widgets/odeditor/objectaccessbox.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/odeditor/odeditorbits.h"
#include "widgets/odeditor/odeditorfilter.h"
#include "widgets/odeditor/odeditormodel.h"
#include "widgets/parameters/paramcomparemodel.h"
#include "widgets/scope/scopepage.h"

#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTreeView>

using namespace db;
using db::test::FakeConnection;
using db::widgets::ObjectAccessBox;
using db::widgets::OdEditor;
using db::widgets::OdEditorModel;

namespace {

constexpr ObjectAddress kAcceleration { 372, 2 };
constexpr ObjectAddress kAccelerationSet1 { 372, 1 };
constexpr ObjectAddress kLanguage { 12, 0 };

ObjectDictionary inverterDictionary()
{
    ObjectDictionary dict;
    const auto add = [&dict](ObjectAddress a, const char *name) {
        ObjectDef def;
        def.address = a;
        def.name = QString::fromLatin1(name);
        def.type = DataType::Unsigned16;
        def.access = Access::ReadWrite;
        def.maximum = 1000u;
        def.storable = true;
        dict.insert(def);
    };
    add(kAccelerationSet1, "Acceleration");
    add(kAcceleration, "Acceleration");
    add(kLanguage, "Language");
    return dict;
}

std::unique_ptr<FakeConnection> inverter()
{
    auto fake = std::make_unique<FakeConnection>(QStringLiteral("fake://inverter"));
    fake->setAddressFormat(AddressFormat::parameter());
    fake->setDictionary(inverterDictionary());
    fake->setValue(kAccelerationSet1, 100u);
    fake->setValue(kAcceleration, 250u);
    fake->setValue(kLanguage, 1u);
    fake->setValue({ 0x372, 2 }, 999u); // what a hex reading of "372:2" would find
    return fake;
}

} // namespace

class TestAddresses : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void editorShowsDecimalAddresses();
    void editorFilterDragAndStatusUseTheFormat();
    void canopenEditorIsUnchanged();
    void accessBoxReadsTheParameterTyped();
    void scopeTakesDecimalAddresses();
    void comparisonShowsTheSetFormat();
};

void TestAddresses::editorShowsDecimalAddresses()
{
    auto fake = inverter();
    OdEditor editor;
    editor.setConnection(fake.get());
    OdEditorModel *model = editor.model();
    QCOMPARE(model->data(model->indexOf(kAcceleration, OdEditorModel::Address)).toString(),
             QStringLiteral("372:2"));
    QCOMPARE(model->data(model->indexOf(kLanguage, OdEditorModel::Address)).toString(),
             QStringLiteral("12:0"));
    // Object row of parameter 372 (two data sets) shows the number alone, in decimal; the tree
    // has one "Parameters" group instead of the CANopen ranges.
    const QModelIndex object = model->parent(model->indexOf(kAcceleration));
    QCOMPARE(model->data(object.siblingAtColumn(OdEditorModel::Address)).toString(),
             QStringLiteral("372"));
    QCOMPARE(model->rowCount(), 1);
    QCOMPARE(model->data(model->index(0, 0)).toString(), QStringLiteral("Parameters"));
    // The details title names it the same way.
    editor.details()->setObject(model->definition(kAcceleration));
    const QString title =
        editor.details()->findChild<QLabel *>(QStringLiteral("detailsTitle"))->text();
    QVERIFY2(title.contains(QLatin1String("372:2")), qPrintable(title));
    // Values are read from parameter 372 data set 2.
    fake->open();
    QTRY_VERIFY(fake->isConnected());
    QTRY_COMPARE(model->data(model->indexOf(kAcceleration, OdEditorModel::Value)).toString(),
                 QStringLiteral("250"));
}

void TestAddresses::editorFilterDragAndStatusUseTheFormat()
{
    auto fake = inverter();
    OdEditor editor;
    editor.setConnection(fake.get());
    fake->open();
    QTRY_VERIFY(fake->isConnected());
    editor.filter()->setText(QStringLiteral("372:2"));
    QModelIndex found = editor.filter()->mapFromSource(editor.model()->indexOf(kAcceleration));
    QVERIFY(found.isValid());
    QVERIFY(!editor.filter()->mapFromSource(editor.model()->indexOf(kLanguage)).isValid());
    editor.filter()->setText(QString());

    std::unique_ptr<QMimeData> mime(editor.model()->mimeData(
        { editor.model()->indexOf(kAcceleration), editor.model()->indexOf(kLanguage) }));
    QVERIFY(mime);
    const QString dragged =
        QString::fromUtf8(mime->data(QString::fromLatin1(OdEditorModel::kMimeType)));
    QVERIFY2(dragged.startsWith(QLatin1String("addresses parameter\n")), qPrintable(dragged));
    const QStringList lines = dragged.split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), 3);
    QVERIFY2(lines.contains(QStringLiteral("372:2")), qPrintable(dragged));
    QVERIFY2(lines.contains(QStringLiteral("12:0")), qPrintable(dragged));
    // The scope reads the drag back to the same objects.
    const auto dropped = widgets::ScopePage::parseObjects(mime.get(), AddressFormat::parameter());
    QVERIFY2(dropped, qPrintable(dropped.error().toString()));
    QVERIFY(dropped->contains(kAcceleration) && dropped->contains(kLanguage));

    // A refused value names the parameter in decimal.
    QVERIFY(!editor.model()->setData(editor.model()->indexOf(kAcceleration, OdEditorModel::Value),
                                     QStringLiteral("5000"), Qt::EditRole));
    QSignalSpy written(&editor, &OdEditor::writeFinished);
    QVERIFY(editor.model()->setData(editor.model()->indexOf(kAcceleration, OdEditorModel::Value),
                                    QStringLiteral("300"), Qt::EditRole));
    QTRY_COMPARE(written.count(), 1);
    QVERIFY2(editor.statusText().contains(QLatin1String("372:2")), qPrintable(editor.statusText()));
    QCOMPARE(fake->writes.last().first, kAcceleration);
}

void TestAddresses::canopenEditorIsUnchanged()
{
    FakeConnection fake;
    ObjectDictionary dict;
    ObjectDef def;
    def.address = { 0x6041, 0 };
    def.name = QStringLiteral("Statusword");
    def.type = DataType::Unsigned16;
    dict.insert(def);
    fake.setDictionary(dict);
    OdEditor editor;
    editor.setConnection(&fake);
    QCOMPARE(editor.model()
                 ->data(editor.model()->indexOf({ 0x6041, 0 }, OdEditorModel::Address))
                 .toString(),
             QStringLiteral("6041:0"));
    std::unique_ptr<QMimeData> mime(
        editor.model()->mimeData({ editor.model()->indexOf({ 0x6041, 0 }) }));
    QCOMPARE(QString::fromUtf8(mime->data(QString::fromLatin1(OdEditorModel::kMimeType))),
             QStringLiteral("6041:0"));
}

void TestAddresses::accessBoxReadsTheParameterTyped()
{
    auto fake = inverter();
    ObjectAccessBox box;
    box.setConnection(fake.get());
    fake->open();
    QTRY_VERIFY(fake->isConnected());
    QCOMPARE(box.findChild<QLineEdit *>(QStringLiteral("address"))->placeholderText(),
             QStringLiteral("372:2"));
    box.setAddressText(QStringLiteral("372:2"));
    QSignalSpy finished(&box, &ObjectAccessBox::finished);
    box.read();
    QTRY_COMPARE(finished.count(), 1);
    QVERIFY2(finished.first().first().toBool(), qPrintable(box.resultText()));
    QVERIFY2(box.resultText().contains(QLatin1String("250")), qPrintable(box.resultText()));
    box.setAddressText(QStringLiteral("6041:0A"));
    box.read();
    QTRY_COMPARE(finished.count(), 2);
    QVERIFY2(box.resultText().contains(QLatin1String("NUMBER:DATASET")),
             qPrintable(box.resultText()));
}

void TestAddresses::scopeTakesDecimalAddresses()
{
    QMimeData decimal;
    decimal.setData(QString::fromLatin1(widgets::ScopePage::kObjectsMimeType),
                    "addresses parameter\n372:2\n12:0\n");
    const auto parsed = widgets::ScopePage::parseObjects(&decimal, AddressFormat::parameter());
    QVERIFY2(parsed, qPrintable(parsed.error().toString()));
    QCOMPARE(*parsed, (QList<ObjectAddress> { kAcceleration, kLanguage }));
    // Objects of a CANopen device are not this device's objects, and the other way round.
    QMimeData hex;
    hex.setData(QString::fromLatin1(widgets::ScopePage::kObjectsMimeType), "372:2\n");
    const auto refused = widgets::ScopePage::parseObjects(&hex, AddressFormat::parameter());
    QVERIFY(!refused);
    QVERIFY2(refused.error().message().contains(QLatin1String("canopen")),
             qPrintable(refused.error().message()));
    QVERIFY(!widgets::ScopePage::parseObjects(&decimal, AddressFormat::canopen()));

    auto fake = inverter();
    fake->open();
    QTRY_VERIFY(fake->isConnected());
    widgets::ScopePage page;
    page.setConnection(fake.get());
    QVERIFY(page.addChannels({ kAcceleration }));
    const auto again = page.addChannels({ kAcceleration });
    QVERIFY(!again);
    QVERIFY2(again.error().message().contains(QLatin1String("372:2 is already recorded")),
             qPrintable(again.error().message()));
    auto *edit = page.findChild<QLineEdit *>(QStringLiteral("scopeAddress"));
    QVERIFY(edit);
    QVERIFY2(edit->placeholderText().contains(QLatin1String("372:2")),
             qPrintable(edit->placeholderText()));
}

void TestAddresses::comparisonShowsTheSetFormat()
{
    ParameterSet device;
    device.addressFormat = &AddressFormat::parameter();
    device.insert({ kAcceleration, QStringLiteral("Acceleration"), DataType::Unsigned16,
                    codec::normalize(DataType::Unsigned16, 250u).value(), QString() });
    ParameterSet file = device;
    file.insert({ kAcceleration, QStringLiteral("Acceleration"), DataType::Unsigned16,
                  codec::normalize(DataType::Unsigned16, 300u).value(), QString() });
    const ParameterComparison comparison = compareParameterSets(
        { device, file }, { QStringLiteral("Device"), QStringLiteral("File") });
    widgets::ParamCompareModel model;
    model.setComparison(comparison, ParameterSet(), inverterDictionary());
    QCOMPARE(model.data(model.index(0, widgets::ParamCompareModel::Address)).toString(),
             QStringLiteral("372:2"));
    QCOMPARE(model.headerData(widgets::ParamCompareModel::Address, Qt::Horizontal).toString(),
             QStringLiteral("Address"));
}

QTEST_MAIN(TestAddresses)
#include "tst_addresses.moc"
