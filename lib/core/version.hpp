#pragma once
// The toolkit's version string: "<project version>-<git describe>" when built from a checkout.
namespace cmp {
const char* version();
}
