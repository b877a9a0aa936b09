"""This machine's network interfaces, as `ros2 doctor --report` lists them.

Read through psutil (getifaddrs / SIOCGIFFLAGS), so the values are whatever
this machine has.  Each interface is an ordered mapping with Jazzy's keys in
Jazzy's order: inet, inet4, ether, inet6, netmask, device, flags, mtu,
broadcast; keys without a value are left out (the loopback has no `ether`).
"""
from __future__ import annotations

import socket

import psutil

# Kernel interface flags (IFF_*, <linux/if.h>): the number before the names in
# `flags : 4163<UP,BROADCAST,RUNNING,MULTICAST>`.
_IFF_BITS = {
    'up': 0x1, 'broadcast': 0x2, 'debug': 0x4, 'loopback': 0x8, 'pointopoint': 0x10,
    'notrailers': 0x20, 'running': 0x40, 'noarp': 0x80, 'promisc': 0x100,
    'allmulti': 0x200, 'master': 0x400, 'slave': 0x800, 'multicast': 0x1000,
    'portsel': 0x2000, 'automedia': 0x4000, 'dynamic': 0x8000,
}
_NO_MAC = '00:00:00:00:00:00'


def format_flags(names: str) -> str:
    """psutil's `up,broadcast,running` -> `67<UP,BROADCAST,RUNNING>` (known flags only)."""
    known = sorted((_IFF_BITS[n], n.upper()) for n in names.split(',') if n in _IFF_BITS)
    return f"{sum(bit for bit, _ in known)}<{','.join(name for _, name in known)}>"


def interfaces() -> list[dict[str, str]]:
    """Every interface of this machine in the system's order, as report fields."""
    stats = psutil.net_if_stats()
    result = []
    for device, addresses in psutil.net_if_addrs().items():
        ipv4 = [a for a in addresses if a.family == socket.AF_INET]
        ipv6 = [a.address for a in addresses if a.family == socket.AF_INET6]
        macs = [a.address for a in addresses
                if a.family == psutil.AF_LINK and a.address and a.address != _NO_MAC]
        fields: dict[str, str] = {}
        if ipv4:
            fields['inet'] = ipv4[0].address
            fields['inet4'] = str([a.address for a in ipv4])
        if macs:
            fields['ether'] = macs[0]
        if ipv6:
            fields['inet6'] = str(ipv6)
        if ipv4 and ipv4[0].netmask:
            fields['netmask'] = ipv4[0].netmask
        fields['device'] = device
        if device in stats:
            fields['flags'] = format_flags(stats[device].flags)
            fields['mtu'] = str(stats[device].mtu)
        if ipv4 and ipv4[0].broadcast:
            fields['broadcast'] = ipv4[0].broadcast
        result.append(fields)
    return result
