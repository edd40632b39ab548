// Checks that the start-up code did its three jobs before main: .data copied from flash,
// .bss zeroed, static constructors run. (Trivially true on host, where the OS does them.)
#pragma once

namespace spanlight::selftest {

bool startup_state_ok();

}  // namespace spanlight::selftest
