// The OpenCL C API with the engine's error check: every failing call becomes a gdr::DeviceError
// naming the call and the OpenCL error code.
#pragma once
#include <CL/cl.h>
#include <CL/cl_ext.h>

#include <string>

#include "util/error.h"

namespace gdr {

class DeviceError : public Error {
 public:
  using Error::Error;
};

const char* cl_error_name(cl_int code);

inline void cl_check(cl_int code, const char* what) {
  if (code != CL_SUCCESS) throw DeviceError(std::string(what) + " failed: " + cl_error_name(code));
}

}  // namespace gdr
