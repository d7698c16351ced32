#pragma once

// A line of simulated NM17x displays on one CAN bus, for `drivebench-sim nm17x`, the demo and
// the tests: served as SLCAN over TCP (127.0.0.1) and/or on a Qt virtualcan interface, with a
// line-based control socket on which a test or the demo plays the operator:
//   list                      one line per display: index, variant, serial, node, position,
//                             status, errors, addressing state; then "ok"
//   turn INDEX DELTA          turn the shaft of display INDEX (1-based) by DELTA 1/100 mm
//   key INDEX left|right [MS] press a key for MS ms (default 100)
//   fault INDEX motor|sensor|blocked|wiring|none   motor fault (Er 4 on the next drive
//                             command), sensor fault (NM174: Er C, motor off), shaft blocked
//                             (Er 3 after 2047h:02), motor wired the wrong way round (Er 6), or
//                             none of them
//   glitch INDEX STEPS [READINGS]   the sensor reads STEPS off for READINGS readings (10 ms
//                             each; default 1; 0 = for good); the jump filter 2005h decides
//   coast INDEX MS            the spindle runs on MS ms after the motor stops (default 0)
//   input INDEX F G           the levels (0/1) of the external inputs F and G (2041h:03 modes)
// Every command is answered with "ok" or "error: <cause>" on its own line.

#include "devices/nm17x/nm17xdescription.h"

#include "core/result.h"

#include <QList>
#include <QObject>

#include <memory>

namespace db::nm17x {

class SimulatedNm17x;

struct SimDeviceSpec
{
    Variant variant = Variant::Nm172;
    canopen::NodeId node = kDeliveryNodeId;
};

class Nm17xSim : public QObject
{
    Q_OBJECT
public:
    static constexpr quint32 kFirstSerial = 0x4D52F567;

    explicit Nm17xSim(QObject *parent = nullptr);
    ~Nm17xSim() override;

    // "nm172@127,nm172@127,nm174@5"; InvalidArgument names the bad item.
    static Result<QList<SimDeviceSpec>> parseDevices(const QString &text);

    // Builds the displays; serial numbers count up from kFirstSerial in list order.
    void create(const QList<SimDeviceSpec> &devices);
    QList<SimulatedNm17x *> devices() const;

    // The bus's bit rate for SLCAN clients (0: any; the default). Set before startSlcan().
    void setBitrate(int bitsPerSecond);
    Result<void> startSlcan(quint16 port = 0);
    quint16 slcanPort() const;
    Result<void> startVirtualCan(const QString &interfaceName);
    Result<void> startControl(quint16 port = 0);
    quint16 controlPort() const;

    // One control command (see above); the reply lines without the final newline.
    QString execute(const QString &line);
    // "NM172 node 127, NM172 node 127, NM174 node 5"
    QString describe() const;

private:
    void startDevices();

    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace db::nm17x
