// How many CPUs this process may run on (affinity mask, not the machine's core count).
#pragma once

namespace gdr {
int usable_cpu_count();
}
