#include "exit_codes.hpp"

#include <iostream>
#include <new>

#include "styk/core/diagnostics.hpp"

namespace styk::cli {

int run_reporting_errors(const std::function<int()>& command) {
  try {
    return command();
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return kBadInput;
  } catch (const NotConvergedError& e) {
    std::cerr << "not converged: " << e.what() << "\n";
    return kNotConverged;
  } catch (const std::bad_alloc&) {
    std::cerr << "internal error: out of memory\n";
    return kInternalError;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kInternalError;
  }
}

}  // namespace styk::cli
