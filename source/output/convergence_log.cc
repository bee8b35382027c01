#include <tissue_contact/output/convergence_log.h>

#include <deal.II/base/exceptions.h>

#include <iomanip>

namespace TissueContact
{
  namespace Output
  {
    ConvergenceLog::ConvergenceLog(std::ostream      &screen,
                                   const std::string &csv_file,
                                   const bool         append)
      : screen(screen)
      , csv(csv_file, append ? std::ios::app : std::ios::trunc)
    {
      AssertThrow(csv.good(),
                  dealii::ExcMessage("cannot write the convergence log '" +
                                     csv_file + "'"));
      if (!append)
        csv << "increment,load_factor,iteration,residual_norm,update_norm,"
               "step_length,linear_iterations\n"
            << std::flush;
    }


    void
    ConvergenceLog::iteration(const IterationInfo &i)
    {
      if (i.increment != last_increment || i.iteration == 0)
        {
          screen << "Increment " << i.increment << ", load factor "
                 << std::setprecision(6) << i.load_factor << "\n"
                 << "  iter   |R|          |du|         step   lin.its\n";
          last_increment = i.increment;
        }
      screen << "  " << std::setw(4) << i.iteration << "   " << std::scientific
             << std::setprecision(3) << i.residual_norm;
      if (i.step_length > 0.)
        screen << "    " << i.update_norm << "    " << std::defaultfloat
               << std::setw(6) << std::left << i.step_length << std::right
               << " " << i.linear_iterations;
      else
        screen << std::defaultfloat << "    converged"
               << (i.at_rounding ?
                     " to rounding: |R| is at its rounding floor, "
                     "above the tolerance the load sets" :
                     "");
      // flushed: a log redirected to a file shows every iteration at once
      screen << std::defaultfloat << std::endl;

      csv << i.increment << "," << std::setprecision(10) << i.load_factor << ","
          << i.iteration << "," << std::scientific << std::setprecision(8)
          << i.residual_norm << "," << i.update_norm << "," << std::defaultfloat
          << i.step_length << "," << i.linear_iterations << "\n"
          << std::flush;
    }


    void
    ConvergenceLog::cutback(const double load_factor, const std::string &why)
    {
      screen << "  increment to load factor " << std::setprecision(6)
             << load_factor << " failed: " << why << std::endl;
    }
  } // namespace Output
} // namespace TissueContact
