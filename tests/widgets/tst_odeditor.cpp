#include "common/demodrive.h"
#include "common/protocols.h"
#include "devices/movingcap/movingcapdrive.h"
#include "fakeconnection.h"
#include "resources/builtindescriptions.h"
#include "widgets/common/lamp.h"
#include "widgets/common/widgetstyle.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/odeditor/odeditorbits.h"
#include "widgets/odeditor/odeditorfilter.h"
#include "widgets/odeditor/odeditormodel.h"
#include "widgets/odeditor/odeditorpoller.h"

#include <QElapsedTimer>
#include <QHeaderView>
#include <QLineEdit>
#include <QMimeData>
#include <QPointer>
#include <QProgressBar>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>
#include <QTreeView>

using namespace db;
using db::test::FakeConnection;
using db::widgets::OdEditor;
using db::widgets::OdEditorModel;

namespace {
constexpr ObjectAddress kVelocity { 0x6081, 0 }; // rw, UNSIGNED32, no limits
constexpr ObjectAddress kAcceleration { 0x6083, 0 }; // rw, 1 .. 20000
constexpr ObjectAddress kStatusword { 0x6041, 0 }; // ro, bit fields
constexpr ObjectAddress kMode { 0x6060, 0 }; // rw, enumeration
} // namespace

// Level 4: the object-dictionary editor offscreen, against the FakeConnection and against the
// in-process simulated MovingCap over loopback RefGo.
class TestOdEditor : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<FakeConnection> m_fake;
    std::unique_ptr<OdEditor> m_editor;

    QModelIndex viewIndex(ObjectAddress a, int column)
    {
        return m_editor->filter()->mapFromSource(m_editor->model()->indexOf(a, column));
    }

    // Opens the value editor of `a` in the tree, types `text` and presses Enter.
    void typeValue(ObjectAddress a, const QString &text)
    {
        QTreeView *view = m_editor->view();
        const QModelIndex index = viewIndex(a, OdEditorModel::Value);
        QVERIFY(index.isValid());
        view->scrollTo(index);
        view->setCurrentIndex(index);
        view->edit(index);
        auto *edit = view->viewport()->findChild<QLineEdit *>();
        QVERIFY(edit);
        edit->selectAll();
        QTest::keyClicks(edit, text);
        QPointer<QLineEdit> guard(edit);
        QTest::keyClick(edit, Qt::Key_Return);
        QTRY_VERIFY(guard.isNull()); // the view commits and closes the editor from the loop
    }

    void startFake()
    {
        m_fake = std::make_unique<FakeConnection>();
        m_fake->setDictionary(resources::movingCapDictionary());
        for (const ObjectDef &def : m_fake->dictionary().objects()) {
            QVariant raw = def.defaultValue.isValid() ? def.defaultValue
                                                      : codec::normalize(def.type, 0).valueOr({});
            m_fake->setValue(def.address, raw);
        }
        m_fake->setValue(kStatusword, QVariant::fromValue<qulonglong>(0x0427));
        m_fake->setValue(kVelocity, QVariant::fromValue<qulonglong>(100));
        m_fake->setValue(kMode, QVariant::fromValue<qlonglong>(1));
        m_editor = std::make_unique<OdEditor>();
        m_editor->resize(1200, 700);
        m_editor->setConnection(m_fake.get());
        m_editor->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_editor.get()));
        m_fake->open();
        QTRY_VERIFY(m_fake->isConnected());
        QTRY_VERIFY(m_editor->model()->value(kVelocity).isValid());
    }

private Q_SLOTS:
    void cleanup()
    {
        m_editor.reset();
        m_fake.reset();
    }

    void treeIsGroupedAndComplete()
    {
        startFake();
        OdEditorModel *model = m_editor->model();
        QCOMPARE(model->addresses().size(), m_fake->dictionary().size());
        QStringList groups;
        for (int row = 0; row < model->rowCount(); ++row)
            groups.append(model->index(row, 0).data().toString());
        QCOMPARE(groups.size(), 3);
        QVERIFY(groups[0].startsWith(QStringLiteral("Communication")));
        QVERIFY(groups[1].startsWith(QStringLiteral("Manufacturer")));
        QVERIFY(groups[2].startsWith(QStringLiteral("Device profile")));
        // 1018h is a record: object row with one child per sub-index.
        const QModelIndex vendor = model->indexOf({ 0x1018, 1 });
        QVERIFY(vendor.isValid());
        QCOMPARE(vendor.parent().data().toString(), QStringLiteral("1018"));
        QCOMPARE(model->rowCount(vendor.parent()), 5);
        QCOMPARE(model->indexOf(kStatusword, OdEditorModel::Type).data().toString(),
                 QStringLiteral("UNSIGNED16"));
        QCOMPARE(model->indexOf(kAcceleration, OdEditorModel::Limits).data().toString(),
                 QStringLiteral("1 … 20000"));
        QCOMPARE(model->indexOf(kMode, OdEditorModel::Value).data().toString(),
                 QStringLiteral("1 (Profile position)"));
    }

    void invalidInputIsRefusedAndNothingSent()
    {
        startFake();
        typeValue(kAcceleration, QStringLiteral("50000")); // above the maximum 20000
        QCOMPARE(m_editor->model()->state(kAcceleration), OdEditorModel::CellState::Refused);
        QVERIFY2(m_editor->statusText().contains(QStringLiteral("range")),
                 qPrintable(m_editor->statusText()));
        const QModelIndex value = m_editor->model()->indexOf(kAcceleration, OdEditorModel::Value);
        QVERIFY(!value.data(Qt::ToolTipRole).toString().isEmpty());
        typeValue(kVelocity, QStringLiteral("fast"));
        QCOMPARE(m_editor->model()->state(kVelocity), OdEditorModel::CellState::Refused);
        typeValue(kVelocity, QStringLiteral("-5")); // UNSIGNED32
        QCOMPARE(m_editor->model()->state(kVelocity), OdEditorModel::CellState::Refused);
        // A write is counted when it is requested, before any answer: nothing to wait for.
        QCOMPARE(m_fake->writeCount, 0);
        QVERIFY(m_fake->writes.isEmpty());
    }

    void readOnlyIsNotEditable()
    {
        startFake();
        const QModelIndex index = viewIndex(kStatusword, OdEditorModel::Value);
        QVERIFY(!(index.flags() & Qt::ItemIsEditable));
        m_editor->view()->edit(index);
        QVERIFY(!m_editor->view()->viewport()->findChild<QLineEdit *>());
        QVERIFY(viewIndex(kVelocity, OdEditorModel::Value).flags() & Qt::ItemIsEditable);
        // Not editable either while disconnected.
        m_fake->goAway();
        QVERIFY(!(viewIndex(kVelocity, OdEditorModel::Value).flags() & Qt::ItemIsEditable));
    }

    void deviceErrorIsShownNextToTheValue()
    {
        startFake();
        m_fake->setFailure(kVelocity,
                           Error(Error::Kind::DeviceError, QStringLiteral("SDO abort 06090030")));
        QSignalSpy finished(m_editor.get(), &OdEditor::writeFinished);
        typeValue(kVelocity, QStringLiteral("250"));
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(finished.first().at(1).toBool(), false);
        QCOMPARE(m_editor->model()->state(kVelocity), OdEditorModel::CellState::WriteFailed);
        const QModelIndex value = m_editor->model()->indexOf(kVelocity, OdEditorModel::Value);
        QVERIFY(value.data(OdEditorModel::StatusTextRole)
                    .toString()
                    .contains(QStringLiteral("06090030")));
        QVERIFY(m_editor->statusText().contains(QStringLiteral("06090030")));
    }

    void scaledObjectsTakeThePhysicalValue()
    {
        startFake();
        constexpr ObjectAddress kStall { 0x3401, 24 }; // UNSIGNED16, factor 0.1, "%"
        QCOMPARE(m_editor->model()->indexOf(kStall, OdEditorModel::Value).data().toString(),
                 QStringLiteral("10")); // raw default 100
        typeValue(kStall, QStringLiteral("12.5"));
        QTRY_COMPARE(m_fake->value(kStall).toULongLong(), 125ull);
    }

    void objectsMissingFromTheDescription()
    {
        startFake();
        constexpr ObjectAddress kUnknown { 0x2FFF, 0 };
        m_fake->setValue(kUnknown, QVariant::fromValue<qlonglong>(42));
        ObjectDef def; // as the "By index…" dialog makes it
        def.address = kUnknown;
        def.type = DataType::Integer64;
        m_editor->model()->addExtraObject(def);
        const QModelIndex row = m_editor->model()->indexOf(kUnknown);
        QVERIFY(row.isValid());
        QVERIFY(row.parent().data().toString().startsWith(QStringLiteral("Not in")));
        QVERIFY(m_editor->model()->value(kVelocity).isValid()); // other values are kept
        m_editor->readAll();
        QTRY_COMPARE(m_editor->model()->value(kUnknown).toLongLong(), 42ll);
        typeValue(kUnknown, QStringLiteral("-7"));
        QTRY_COMPARE(m_fake->value(kUnknown).toLongLong(), -7ll);
    }

    void filterByIndexNameAndValue()
    {
        startFake();
        widgets::OdEditorFilter *filter = m_editor->filter();
        const auto shown = [this](ObjectAddress a) {
            return viewIndex(a, 0).isValid();
        };
        for (const QString &text :
             { QStringLiteral("6041"), QStringLiteral("0x6041"), QStringLiteral("6041h"),
               QStringLiteral("6041:0"), QStringLiteral("statusWORD") }) {
            m_editor->setFilterText(text);
            QVERIFY2(shown(kStatusword), qPrintable(text));
            QVERIFY2(!shown(kVelocity), qPrintable(text));
        }
        m_editor->setFilterText(QStringLiteral("profile position"));
        QVERIFY(shown(kMode)); // by the value's enumeration name
        m_editor->setFilterText(QStringLiteral("identity"));
        QVERIFY(shown({ 0x1018, 4 })); // an object's name shows all its sub-indices
        m_editor->setFilterText(QStringLiteral("no such object"));
        QCOMPARE(filter->rowCount(), 0);
        m_editor->setFilterText(QString());
        QCOMPARE(filter->rowCount(), 3);
    }

    void hexToggle()
    {
        startFake();
        const QModelIndex velocity = m_editor->model()->indexOf(kVelocity, OdEditorModel::Value);
        const QModelIndex status = m_editor->model()->indexOf(kStatusword, OdEditorModel::Value);
        QCOMPARE(velocity.data().toString(), QStringLiteral("100")); // the unit has a column
        QCOMPARE(m_editor->model()->indexOf(kVelocity, OdEditorModel::Unit).data().toString(),
                 QStringLiteral("units/s"));
        QCOMPARE(status.data().toString(), QStringLiteral("0x0427")); // bit words: always hex
        // Identifiers too: device type, identity, whatever the toggle says.
        QCOMPARE(m_editor->model()
                     ->indexOf(ObjectAddress(0x1000, 0), OdEditorModel::Value)
                     .data()
                     .toString(),
                 QStringLiteral("0x00020192"));
        QVERIFY(m_editor->model()
                    ->indexOf(ObjectAddress(0x1018, 1), OdEditorModel::Value)
                    .data()
                    .toString()
                    .startsWith(QStringLiteral("0x")));
        m_editor->setHex(true);
        QCOMPARE(velocity.data().toString(), QStringLiteral("0x00000064"));
        QCOMPARE(velocity.data(Qt::EditRole).toString(), QStringLiteral("0x00000064"));
        QCOMPARE(m_editor->model()->indexOf(kMode, OdEditorModel::Value).data().toString(),
                 QStringLiteral("0x01 (Profile position)"));
        QCOMPARE(status.data().toString(), QStringLiteral("0x0427"));
        m_editor->setHex(false);
        QCOMPARE(velocity.data().toString(), QStringLiteral("100"));
    }

    // After the link went away the values stay, greyed out as possibly out of date.
    void valuesOfALostConnectionAreStale()
    {
        startFake();
        const QModelIndex velocity = m_editor->model()->indexOf(kVelocity, OdEditorModel::Value);
        QVERIFY(!velocity.data(Qt::ForegroundRole).isValid());
        m_fake->goAway();
        QTRY_VERIFY(velocity.data(Qt::ForegroundRole).isValid());
        QCOMPARE(velocity.data(Qt::ForegroundRole).value<QColor>(),
                 widgets::style::inactiveColor());
        QCOMPARE(velocity.data().toString(), QStringLiteral("100")); // still shown
        QVERIFY(velocity.data(Qt::ToolTipRole).toString().contains(QStringLiteral("out of date")));
    }

    // Read all shows how far it got and can be cancelled: what was not sent is not sent.
    void readAllShowsProgressAndCancels()
    {
        startFake();
        m_editor->poller()->setPeriodMs(0);
        QTRY_COMPARE(m_editor->poller()->pending(), 0);
        QTRY_COMPARE(m_editor->poller()->inFlight(), 0);
        m_fake->replyDelayMs = 30;
        auto *progress = m_editor->findChild<QProgressBar *>(QStringLiteral("readAllProgress"));
        auto *cancel = m_editor->findChild<QToolButton *>(QStringLiteral("cancelReadAll"));
        QVERIFY(progress && cancel);
        QVERIFY(!progress->isVisible());
        m_editor->readAll();
        QTRY_VERIFY(progress->isVisible() && cancel->isVisible());
        QVERIFY(progress->maximum() > 100); // every readable object of the description
        QTRY_VERIFY(progress->value() >= 3);
        const int total = progress->maximum();
        const int readsBefore = m_fake->readCount - progress->value();
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(!progress->isVisible());
        QTRY_COMPARE(m_editor->poller()->inFlight(), 0);
        QCOMPARE(m_editor->poller()->pending(), 0);
        const int reads = m_fake->readCount;
        QVERIFY(reads - readsBefore < total / 2);
        // Nothing else is sent (the refresh rate is off).
        QVERIFY(!QTest::qWaitFor([&] { return m_fake->readCount > reads; }, 300));
    }

    // Values that differ from the description's default stand out; the name column keeps its
    // width in a narrow window.
    void differencesFromTheDefaultAndStableColumns()
    {
        startFake();
        const ObjectDef *def = m_editor->model()->definition(kAcceleration);
        QVERIFY(def && def->defaultValue.isValid());
        m_fake->setValue(kAcceleration, QVariant::fromValue<qulonglong>(2000)); // default 1000
        m_editor->readAll();
        QTRY_COMPARE(m_editor->model()->value(kAcceleration).toULongLong(), 2000ULL);
        const QModelIndex changed = m_editor->model()->indexOf(kAcceleration, OdEditorModel::Value);
        QVERIFY(changed.data(Qt::FontRole).value<QFont>().bold());
        QVERIFY(changed.data(Qt::BackgroundRole).isValid());
        QVERIFY(changed.data(Qt::ToolTipRole).toString().contains(QStringLiteral("default")));
        const QModelIndex same =
            m_editor->model()->indexOf(ObjectAddress(0x6084, 0), OdEditorModel::Value);
        QVERIFY(same.data().isValid());
        QVERIFY(!same.data(Qt::FontRole).value<QFont>().bold());
        QVERIFY(!same.data(Qt::BackgroundRole).isValid());

        m_editor->resize(640, 500);
        QTRY_COMPARE(m_editor->width(), 640);
        m_editor->setConnection(nullptr);
        m_editor->setConnection(m_fake.get()); // a new dictionary resets the model
        QCOMPARE(m_editor->view()->header()->sectionSize(OdEditorModel::Name),
                 OdEditor::kNameColumnWidth);
    }

    void bitFieldsOfTheSelectedWord()
    {
        startFake();
        m_editor->view()->setCurrentIndex(viewIndex(kStatusword, OdEditorModel::Name));
        widgets::OdBitFieldView *bits = m_editor->details();
        QVERIFY(bits->lamp(10));
        QTRY_VERIFY(!bits->lamp(10)->isStale());
        QVERIFY(bits->lamp(10)->isOn()); // 0x0427: target reached
        QVERIFY(bits->lamp(0)->isOn());
        QVERIFY(!bits->lamp(3)->isOn()); // no fault
        m_fake->setValue(kStatusword, QVariant::fromValue<qulonglong>(0x0008));
        m_editor->setRefreshPeriodMs(250);
        QTRY_VERIFY(bits->lamp(3)->isOn());
        // CiA 402 names when a description has none.
        ObjectDef bare;
        bare.address = { 0x6041, 0 };
        QCOMPARE(widgets::OdBitFieldView::bitFieldsFor(bare).size(), 13);
    }

    void dragCarriesTheAddresses()
    {
        startFake();
        OdEditorModel *model = m_editor->model();
        const QModelIndexList rows { model->indexOf(kStatusword),
                                     model->indexOf({ 0x1018, 1 }).parent() };
        std::unique_ptr<QMimeData> mime(model->mimeData(rows));
        QVERIFY(mime);
        const QString expected = QStringLiteral("6041:0\n1018:0\n1018:1\n1018:2\n1018:3\n1018:4");
        QCOMPARE(QString::fromUtf8(mime->data(QString::fromLatin1(OdEditorModel::kMimeType))),
                 expected);
        QCOMPARE(mime->text(), expected);
        QVERIFY(model->flags(model->indexOf(kStatusword)) & Qt::ItemIsDragEnabled);
    }

    void liveRefreshReadsOnlyVisibleRowsWithoutFlooding()
    {
        startFake();
        m_fake->replyDelayMs = 5;
        QSignalSpy idle(m_editor->poller(), &widgets::OdEditorPoller::idle);
        QTRY_VERIFY(m_editor->poller()->pending() == 0 && m_editor->poller()->inFlight() == 0);
        const QList<ObjectAddress> visible = m_editor->visibleAddresses();
        QVERIFY(!visible.isEmpty());
        QVERIFY(visible.size() < m_fake->dictionary().size());
        const int before = m_fake->readCount;
        idle.clear();
        m_editor->setRefreshPeriodMs(250);
        QTRY_VERIFY(idle.count() >= 2);
        const int perRound = (m_fake->readCount - before) / idle.count();
        QVERIFY2(perRound <= visible.size(), qPrintable(QString::number(perRound)));
        QVERIFY(m_fake->maxInFlight <= widgets::OdEditorPoller::kMaxInFlight);
        m_editor->setRefreshPeriodMs(0);
        QVERIFY(m_fake->writes.isEmpty()); // values from the device never write back
    }

    void editChangesTheSimulatedDrive()
    {
        app::DemoDrive demo;
        const auto started = demo.startRefgo(0);
        QVERIFY2(started.ok(), qPrintable(started.error().toString()));
        auto created = app::protocolRegistry().create(demo.refgoUri());
        QVERIFY2(created.ok(), qPrintable(created.error().toString()));
        std::shared_ptr<DeviceConnection> connection = created.value();
        m_editor = std::make_unique<OdEditor>();
        m_editor->resize(1200, 700);
        m_editor->setConnection(connection.get());
        m_editor->show();
        QElapsedTimer clock;
        clock.start();
        connection->open();
        QTRY_VERIFY_WITH_TIMEOUT(connection->isConnected(), 10000);
        // The first pass reads every readable object (informative figure, not asserted).
        QTRY_VERIFY_WITH_TIMEOUT(m_editor->model()->value(kAcceleration).isValid()
                                     && m_editor->poller()->pending() == 0
                                     && m_editor->poller()->inFlight() == 0,
                                 10000);
        qInfo("read-all pass: %d requests in %lld ms over RefGo loopback",
              m_editor->poller()->requestsSent(), clock.elapsed());

        typeValue(kAcceleration, QStringLiteral("1234"));
        QTRY_COMPARE_WITH_TIMEOUT(demo.drive().read(kAcceleration).value().toULongLong(), 1234ull,
                                  10000);
        QTRY_COMPARE(m_editor->model()->value(kAcceleration).toULongLong(), 1234ull);

        // An enumeration by name, through the combo box editor's text.
        QVERIFY(m_editor->model()->setData(m_editor->model()->indexOf(kMode, OdEditorModel::Value),
                                           QStringLiteral("Homing")));
        QTRY_COMPARE(demo.drive().read(kMode).value().toLongLong(), 6ll);

        // Refused locally: the drive keeps its value.
        typeValue(kAcceleration, QStringLiteral("0"));
        QCOMPARE(m_editor->model()->state(kAcceleration), OdEditorModel::CellState::Refused);
        QCOMPARE(demo.drive().read(kAcceleration).value().toULongLong(), 1234ull);
        m_editor.reset();
        connection->close();
    }
};

QTEST_MAIN(TestOdEditor)
#include "tst_odeditor.moc"
