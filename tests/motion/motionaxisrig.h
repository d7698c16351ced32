#pragma once

// The command model over Cia402Axis on a test rig (rig.h: the simulated MovingCap in-process,
// over RefGo or over CANopen), shared by the motion tests.
#include "driverig.h"
#include "motion/cia402axis.h"
#include "motion/motionaxis.h"

#include <memory>

namespace db::test {

struct MotionRig
{
    std::unique_ptr<Rig> rig;
    std::unique_ptr<motion::Cia402Axis> cia;
    std::unique_ptr<motion::MotionAxis> axis;
};

// A MotionAxis on rig `kind` (see makeRig), initialised, limited to `maxVelocity` units/s;
// nullptr when the rig or the initialisation fails.
inline std::unique_ptr<MotionRig> makeMotionRig(const QString &kind, double maxVelocity,
                                                const QHash<ObjectAddress, QVariant> &initial = {})
{
    using namespace db::motion;
    auto a = std::make_unique<MotionRig>();
    a->rig = makeRig(kind, initial);
    if (!a->rig)
        return nullptr;
    a->cia = std::make_unique<Cia402Axis>(a->rig->connection.get());
    a->cia->setAccelerationUnit(Cia402Axis::AccelerationUnit::RotaryMotor);
    if (!await(a->cia->initialize()).ok())
        return nullptr;
    a->axis = std::make_unique<MotionAxis>(a->cia.get());
    AxisConfig c;
    c.maxVelocity = maxVelocity;
    c.maxAcceleration = 200000; // 6083h <= 20000 raw = 200000 units/s^2 here
    c.positionWindow = 1.0;
    c.velocityWindow = 10.0;
    a->axis->setConfig(c);
    return a;
}

inline motion::MoveParams moveParams(double position, double velocity, double acceleration)
{
    motion::MoveParams p;
    p.position = position;
    p.velocity = velocity;
    p.acceleration = p.deceleration = acceleration;
    p.jerk = 1e6;
    return p;
}

} // namespace db::test
