#pragma once

#include "core/statussource.h"

namespace db::cia402 {

// The status of a CiA 402 drive (movingcap.md 5, 7, 8.1): statusword 6041h and its state,
// mode 6061h, position, velocity and current, the fault register 1002h (bits 0-15 errors, 16-31
// warnings), the last error 603Fh with the description's text, and the digital I/O 60FDh and
// 60FEh.1. One cycle reads its due objects at once (StatusSource).
class Cia402StatusSource : public StatusSource
{
    Q_OBJECT
public:
    static constexpr int kInputCount = 10; // IN1..IN10 = 60FDh bits 16..25 (movingcap.md 8.1)
    static constexpr int kOutputCount = 4; // OUT1..OUT4 = 60FEh.1 bits 16..19

    explicit Cia402StatusSource(DeviceConnection *connection, QObject *parent = nullptr);

    // The connection's status source; a CiA 402 one, made now, when it has none.
    static StatusSource *sourceOf(DeviceConnection *connection);

    // 6041h, 6061h, 6064h, 606Ch, 6078h, 1002h, 603Fh, 60FDh, 60FEh.1.
    static QList<ObjectAddress> objects();

    QString statusWordLabel() const override;
    QList<StatusLamp> lamps() const override;
    QList<StatusIoRow> ioRows() const override;
    // objects() that the connection's description has: a device without them would answer
    // every round with errors (SDO aborts) and tell nothing.
    QList<ObjectAddress> polledObjects() const override;
    StatusValue mode() const override;
    QList<StatusValue> actualValues() const override;
    StatusValue fault() const override;
    QString faultText() const override;
    bool faultActive() const override;
    StatusValue faultRegister() const override;
    QStringList errorBits() const override;
    QStringList warnings() const override;

protected:
    void poll() override;

private:
    QStringList registerBits(bool warnings) const;
};

} // namespace db::cia402
