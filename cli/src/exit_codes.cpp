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
  } catch (const ResourceLimitError& e) {
    std::cerr << "resource limit: " << e.what() << "\n";
    return kResourceLimit;
  } catch (const std::bad_alloc&) {
    std::cerr << "resource limit: out of memory (the model needs more memory than this machine "
                 "can give; a coarser mesh, a symmetric part of the model or the iterative "
                 "solver need less)\n";
    return kResourceLimit;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kInternalError;
  }
}

}  // namespace styk::cli
