#!/usr/bin/python3
"""A third-party CAN stack (python-can, SLCAN over TCP) talks to `drivebench-sim nm17x` with the
byte sequences the NM17x displays document: LSS addressing by serial number, then the SDO
examples. Usage: nm17x_thirdparty.py SLCAN_PORT. Prints one line per step; exit 0 when every
answer is byte-exact."""
import sys
import time

import can

STEP_TIMEOUT_S = 2.0


def frame(cob_id, hex_bytes):
    return can.Message(arbitration_id=cob_id, data=bytes.fromhex(hex_bytes), is_extended_id=False)


def expect(bus, cob_id, hex_bytes, what):
    deadline = time.monotonic() + STEP_TIMEOUT_S
    want = bytes.fromhex(hex_bytes)
    while time.monotonic() < deadline:
        msg = bus.recv(timeout=0.1)
        if msg is None or msg.arbitration_id != cob_id:
            continue
        if bytes(msg.data) != want:
            sys.exit(f"{what}: got {msg.arbitration_id:03X} {bytes(msg.data).hex(' ')}, "
                     f"expected {cob_id:03X} {want.hex(' ')}")
        print(f"{what}: {cob_id:03X} {want.hex(' ').upper()}")
        return
    sys.exit(f"{what}: no {cob_id:03X} frame within {STEP_TIMEOUT_S} s")


def main():
    port = int(sys.argv[1])
    bus = can.Bus(interface="slcan", channel=f"socket://127.0.0.1:{port}", bitrate=125000)
    try:
        # LSS by serial number (NM172, serial 4D52F567h) as the display's documentation shows it.
        for cob_id, data in [(0x000, "0200"), (0x7E5, "0401"), (0x7E5, "40EC000000000000"),
                             (0x7E5, "4171000000000000"), (0x7E5, "4201000100000000"),
                             (0x7E5, "4367F5524D000000")]:
            bus.send(frame(cob_id, data))
        expect(bus, 0x7E4, "4400000000000000", "LSS switch selective")
        bus.send(frame(0x7E5, "1125"))
        expect(bus, 0x7E4, "1100000000000000", "LSS configure node id 25h")
        bus.send(frame(0x7E5, "1700"))
        expect(bus, 0x7E4, "1700000000000000", "LSS store")
        bus.send(frame(0x7E5, "0400"))
        bus.send(frame(0x000, "8100"))
        expect(bus, 0x725, "00", "boot-up as node 25h")
        # The SDO examples, at node 25h.
        bus.send(frame(0x625, "23036000" "20A10700"))  # preset 5000.00 mm
        expect(bus, 0x5A5, "6003600000000000", "SDO write preset")
        # The display applies a write within its next 10 ms cycle: read until it has.
        deadline = time.monotonic() + STEP_TIMEOUT_S
        while True:
            bus.send(frame(0x625, "4004600000000000"))
            msg = bus.recv(timeout=0.1)
            if msg is not None and bytes(msg.data) == bytes.fromhex("4304600020A10700"):
                print("SDO-1 read position: 5A5 43 04 60 00 20 A1 07 00")
                break
            if time.monotonic() > deadline:
                sys.exit("SDO-1 read position: the preset did not arrive")
        for request, response, what in [
                ("2303200040010000", "6003200000000000", "SDO-2 write tolerance"),
                ("4001210000000000", "4F01210025000000", "SDO-3 read node id"),
                ("2300200501000000", "6000200500000000", "SDO-4 rotate display"),
                ("2300200502000000", "8000200530000906", "SDO-5 out of range")]:
            bus.send(frame(0x625, request))
            expect(bus, 0x5A5, response, what)
    finally:
        bus.shutdown()
    print("ok")


if __name__ == "__main__":
    main()
