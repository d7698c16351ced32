#pragma once

// Simulated NM17x displays on one bus for the device tests: what the master sends reaches all of
// them; what they send is collected.

#include "devices/nm17x/device/nm17xsim.h"
#include "devices/nm17x/device/simulatednm17x.h"

#include <QList>

namespace db::test {

struct Frame
{
    quint32 id;
    QByteArray data;
};

class Line
{
public:
    explicit Line(const QList<nm17x::Variant> &variants, canopen::NodeId node = 127)
    {
        quint32 serial = nm17x::Nm17xSim::kFirstSerial;
        for (const nm17x::Variant v : variants) {
            auto *device = new nm17x::SimulatedNm17x(v, serial++, node);
            QObject::connect(device, &nm17x::SimulatedNm17x::transmit, device,
                             [this](const QCanBusFrame &f) {
                                 frames.append({ f.frameId(), f.payload() });
                             });
            devices.append(device);
        }
        for (nm17x::SimulatedNm17x *device : devices)
            device->start();
    }
    ~Line() { qDeleteAll(devices); }
    Line(const Line &) = delete;
    Line &operator=(const Line &) = delete;
    void send(quint32 id, const char *hex)
    {
        const QCanBusFrame frame(id, QByteArray::fromHex(hex));
        for (nm17x::SimulatedNm17x *device : devices)
            device->receive(frame);
    }
    QList<Frame> take()
    {
        QList<Frame> out = frames;
        frames.clear();
        return out;
    }
    QList<Frame> takeId(quint32 id)
    {
        QList<Frame> out;
        for (const Frame &f : take()) {
            if (f.id == id)
                out.append(f);
        }
        return out;
    }
    QList<nm17x::SimulatedNm17x *> devices;
    QList<Frame> frames;
};

} // namespace db::test
