// Seconds since the process started (the clock starts during static initialisation, before
// main), for start-up figures such as the time to the first kernel launch.
#pragma once

namespace gdr {
double seconds_since_process_start();
}
