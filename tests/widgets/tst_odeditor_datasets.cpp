// Level 4: the object editor against the simulated ACTIVE Cube over VABus/TCP: one column per
// data set for four-data-set parameters and data set 0 for single ones, edits written to the
// data set (EEPROM) or, on request, to its RAM copy (data set + 5), and the device's own error
// text next to a refused value; the parameter names in English and German.

#include "common/protocols.h"
#include "devices/bonfiglioli/simulatedacu.h"
#include "translations/language.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/odeditor/odeditorfilter.h"
#include "widgets/odeditor/odeditormodel.h"

#include <QCheckBox>
#include <QHeaderView>
#include <QTest>
#include <QTreeView>

#include <memory>

using namespace db;
using db::bonfiglioli::SimulatedAcu;
using db::widgets::OdEditor;
using db::widgets::OdEditorModel;

namespace {
constexpr ObjectAddress kFixedFrequency2 { 481, 0 };
constexpr ObjectAddress kMechanicalPower4 { 376, 4 };
constexpr ObjectAddress kSoftwareVersion { 12, 0 };

ObjectAddress dataSet(ObjectAddress parameter, quint8 ds)
{
    return ObjectAddress(parameter.index, ds);
}
} // namespace

class TestOdEditorDataSets : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<SimulatedAcu> m_acu;
    std::shared_ptr<DeviceConnection> m_connection;

    QString cell(const OdEditor &editor, ObjectAddress address, int role = Qt::DisplayRole)
    {
        OdEditorModel *model = editor.model();
        return model->data(model->indexOf(address, OdEditorModel::Value), role).toString();
    }

private Q_SLOTS:
    void init()
    {
        m_acu = std::make_unique<SimulatedAcu>();
        QVERIFY(m_acu->listen(0).ok());
        auto created = app::protocolRegistry().create(
            QStringLiteral("vabus://127.0.0.1:%1").arg(m_acu->port()));
        QVERIFY2(created.ok(), qPrintable(created.error().toString()));
        m_connection = created.value();
    }
    void cleanup()
    {
        i18n::installTranslations(*qApp, QStringLiteral("en"));
        m_connection.reset();
        m_acu.reset();
    }

    void oneColumnPerDataSet()
    {
        OdEditor editor;
        editor.resize(1366, 700);
        editor.setConnection(m_connection.get());
        editor.show();
        OdEditorModel *model = editor.model();
        QVERIFY(model->hasDataSetColumns());
        QCOMPARE(model->columnCount(), int(OdEditorModel::DataSetColumnCount));
        QCOMPARE(model->headerData(OdEditorModel::DataSet1 + 1, Qt::Horizontal).toString(),
                 QStringLiteral("DS 2"));
        QCOMPARE(model->headerData(OdEditorModel::Value, Qt::Horizontal).toString(),
                 QStringLiteral("DS 0"));
        // 481 is one row: its number and name, its data sets in the DS 1-4 columns of that row.
        const QModelIndex ds1 = model->indexOf(dataSet(kFixedFrequency2, 1), OdEditorModel::Value);
        const QModelIndex ds4 = model->indexOf(dataSet(kFixedFrequency2, 4), OdEditorModel::Value);
        QCOMPARE(ds1.column(), int(OdEditorModel::DataSet1));
        QCOMPARE(ds4.column(), int(OdEditorModel::DataSet1) + 3);
        QCOMPARE(ds1.row(), ds4.row());
        QCOMPARE(model->data(ds1.siblingAtColumn(OdEditorModel::Address)).toString(),
                 QStringLiteral("481"));
        QCOMPARE(model->data(ds1.siblingAtColumn(OdEditorModel::Name)).toString(),
                 QStringLiteral("Fixed frequency 2"));
        QVERIFY(!model->data(ds1.siblingAtColumn(OdEditorModel::Value)).isValid());
        // Single parameters keep their value in DS 0 and nothing in the data-set columns.
        const QModelIndex version = model->indexOf(kSoftwareVersion, OdEditorModel::Value);
        QCOMPARE(version.column(), int(OdEditorModel::Value));
        QVERIFY(!model->data(version.siblingAtColumn(OdEditorModel::DataSet1)).isValid());

        m_connection->open();
        QTRY_COMPARE_WITH_TIMEOUT(cell(editor, dataSet(kFixedFrequency2, 1)),
                                  QStringLiteral("10.00"), 10000);
        QTRY_COMPARE(cell(editor, dataSet(kFixedFrequency2, 2)), QStringLiteral("15.00"));
        QTRY_COMPARE(cell(editor, dataSet(kFixedFrequency2, 4)), QStringLiteral("25.00"));
        QCOMPARE(model->data(model->indexOf(dataSet(kFixedFrequency2, 1), OdEditorModel::Unit))
                     .toString(),
                 QStringLiteral("Hz"));
        QTRY_COMPARE(cell(editor, kSoftwareVersion), QStringLiteral("5.3.2 STO"));
        // The editor never reads data set 0 of a four-data-set parameter (it fails with "values
        // of the data sets differ" when they differ).
        QVERIFY(!model->addresses().contains(kFixedFrequency2));
        QCOMPARE(m_acu->eepromWrites(), quint64(0));

        // On screen the data sets stand right of DS 0; a parameter list has no PDO column.
        QHeaderView *header = editor.view()->header();
        QCOMPARE(header->visualIndex(OdEditorModel::DataSet1),
                 header->visualIndex(OdEditorModel::Value) + 1);
        QVERIFY(header->isSectionHidden(OdEditorModel::Pdo));
        editor.setConnection(nullptr);
        QCOMPARE(model->columnCount(), int(OdEditorModel::ColumnCount));
        QVERIFY(!header->isSectionHidden(OdEditorModel::Pdo));
    }

    // In German the editor names the parameters as the inverter's German manual does, the English
    // name in the tooltip; the filter finds a parameter by either name.
    void namesInTheProgramsLanguage_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("fixedFrequency");
        QTest::addColumn<QString>("version");
        QTest::newRow("en") << "en"
                            << "Fixed frequency 2"
                            << "Inverter software version";
        QTest::newRow("de") << "de"
                            << "Festfrequenz 2"
                            << "FU-Softwareversion";
    }
    void namesInTheProgramsLanguage()
    {
        QFETCH(QString, language);
        QFETCH(QString, fixedFrequency);
        QFETCH(QString, version);
        QVERIFY(i18n::installTranslations(*qApp, language));
        OdEditor editor;
        editor.setConnection(m_connection.get());
        OdEditorModel *model = editor.model();
        const QModelIndex ff2 = model->indexOf(dataSet(kFixedFrequency2, 1), OdEditorModel::Name);
        QCOMPARE(model->data(ff2).toString(), fixedFrequency);
        const QModelIndex sw = model->indexOf(kSoftwareVersion, OdEditorModel::Name);
        QCOMPARE(model->data(sw).toString(), version);
        const QString tip = model->data(sw, Qt::ToolTipRole).toString();
        QCOMPARE(tip.contains(QLatin1String("Inverter software version")), language == u"de");

        const auto shown = [&editor](ObjectAddress a) {
            return editor.filter()
                ->mapFromSource(editor.model()->indexOf(a, OdEditorModel::Name))
                .isValid();
        };
        for (const QString &text :
             { QStringLiteral("softwareversion"), QStringLiteral("software version") }) {
            editor.setFilterText(text);
            QVERIFY2(shown(kSoftwareVersion), qPrintable(text));
            QVERIFY2(!shown(dataSet(kFixedFrequency2, 1)), qPrintable(text));
        }
    }

    void editWritesTheDataSetToEeprom()
    {
        OdEditor editor;
        editor.setConnection(m_connection.get());
        QVERIFY(m_connection->openAndWait(3000).ok());
        OdEditorModel *model = editor.model();
        const ObjectAddress ds3 = dataSet(kFixedFrequency2, 3);
        QTRY_VERIFY(editor.model()->flags(model->indexOf(ds3, OdEditorModel::Value))
                    & Qt::ItemIsEditable);
        QVERIFY(model->setData(model->indexOf(ds3, OdEditorModel::Value), QStringLiteral("30.5")));
        QTRY_COMPARE(m_acu->store().value(481, 3).toLongLong(), 3050);
        QTRY_VERIFY(model->state(ds3) != OdEditorModel::CellState::Writing);
        QVERIFY(model->state(ds3) != OdEditorModel::CellState::WriteFailed);
        QCOMPARE(m_acu->store().value(481, 2).toLongLong(), 1500); // the others untouched
        QCOMPARE(m_acu->eepromWrites(), quint64(1));
        QTRY_COMPARE(cell(editor, ds3), QStringLiteral("30.50"));
    }

    void ramChoiceWritesDataSetPlusFive()
    {
        OdEditor editor;
        editor.setConnection(m_connection.get());
        editor.show();
        auto *ram = editor.findChild<QCheckBox *>(QStringLiteral("ramWrites"));
        QVERIFY(ram && ram->isVisible());
        QVERIFY(!editor.writesToRam()); // EEPROM by default
        ram->click();
        QVERIFY(editor.writesToRam());
        QVERIFY(m_connection->openAndWait(3000).ok());
        OdEditorModel *model = editor.model();
        const ObjectAddress ds2 = dataSet(kFixedFrequency2, 2);
        QTRY_VERIFY(model->flags(model->indexOf(ds2, OdEditorModel::Value)) & Qt::ItemIsEditable);
        QVERIFY(model->setData(model->indexOf(ds2, OdEditorModel::Value), QStringLiteral("12.5")));
        QTRY_COMPARE(m_acu->store().value(481, 2).toLongLong(), 1250);
        QTRY_VERIFY(model->state(ds2) != OdEditorModel::CellState::Writing);
        QVERIFY(model->state(ds2) != OdEditorModel::CellState::WriteFailed);
        QCOMPARE(m_acu->eepromWrites(), quint64(0));
        QVERIFY2(editor.statusText().contains(QStringLiteral("481:7")),
                 qPrintable(editor.statusText()));
        QTRY_COMPARE(cell(editor, ds2), QStringLiteral("12.50"));
        // RAM only: after a power cycle the data set holds its stored value again.
        m_acu->powerCycle();
        QCOMPARE(m_acu->store().value(481, 2).toLongLong(), 1500);
    }

    void refusedValueShowsTheDeviceText()
    {
        OdEditor editor;
        editor.setConnection(m_connection.get());
        editor.show();
        QVERIFY(m_connection->openAndWait(3000).ok());
        OdEditorModel *model = editor.model();
        const QModelIndex index = model->indexOf(kMechanicalPower4, OdEditorModel::Value);
        QTRY_VERIFY(model->flags(index) & Qt::ItemIsEditable);
        QVERIFY(model->setData(index, QStringLiteral("0"))); // the inverter refuses 0 kW
        QTRY_COMPARE(model->state(kMechanicalPower4), OdEditorModel::CellState::WriteFailed);
        const QString text = cell(editor, kMechanicalPower4, OdEditorModel::StatusTextRole);
        QVERIFY2(text.contains(QStringLiteral("invalid parameter value")), qPrintable(text));
        QCOMPARE(m_acu->eepromWrites(), quint64(0));
    }
};

QTEST_MAIN(TestOdEditorDataSets)
#include "tst_odeditor_datasets.moc"
