#include "exit_codes.hpp"

#include <iostream>
#include <new>
#include <string>

#include "json_progress.hpp"
#include "styk/core/diagnostics.hpp"

namespace styk::cli {
namespace {

// The one message of a failure: `prefix` + `text` for people, or the protocol's error line.
int report(ErrorOutput output, int code, const char* kind, const std::string& prefix,
           const std::string& text, const SourceLoc& where = {}) {
  if (output == ErrorOutput::JsonLines)
    std::cerr << json_error_line(code, kind, where.file, where.line, text) << "\n";
  else
    std::cerr << prefix << text << "\n";
  return code;
}

}  // namespace

int run_reporting_errors(const std::function<int()>& command, ErrorOutput output) {
  try {
    return command();
  } catch (const InputError& e) {
    if (output == ErrorOutput::JsonLines)
      return report(output, kBadInput, "input", "", e.message(), e.where());
    return report(output, kBadInput, "input", "", e.what());
  } catch (const NotConvergedError& e) {
    return report(output, kNotConverged, "not_converged", "not converged: ", e.what());
  } catch (const ResourceLimitError& e) {
    return report(output, kResourceLimit, "resource_limit", "resource limit: ", e.what());
  } catch (const std::bad_alloc&) {
    return report(output, kResourceLimit, "resource_limit", "resource limit: ",
                  "out of memory (the model needs more memory than this machine can give; a "
                  "coarser mesh, a symmetric part of the model or the iterative solver need "
                  "less)");
  } catch (const std::exception& e) {
    return report(output, kInternalError, "internal", "internal error: ", e.what());
  }
}

}  // namespace styk::cli
