/* Empty stand-in for <sys/resource.h>, which MinGW-w64 lacks. METIS's GKlib includes it on
   every non-MSVC platform but uses getrusage only outside Windows (timers.c). */
