# Sourced by the shell tests that need small SOFA files (ncgen, Debian's
# netcdf-bin; netCDF-4, as SOFA files are). Needs $tmp, a directory.
#
# sofa NAME M R N RATE [LAST [EDIT]]: writes $tmp/NAME.sofa with M
# measurements on the horizon, R receivers, N taps (UNLIMITED: none; a
# pulse at tap 0, LAST in the very last value when not empty), one
# Data.SamplingRate of RATE Hz; the sed script EDIT changes the CDL text
# before ncgen reads it.
sofa() {
    name=$1 m=$2 r=$3 n=$4 rate=$5 last=${6:-} edit=${7:-}
    {
        cat <<CDL
netcdf $name {
dimensions:
	I = 1 ; C = 3 ; R = $r ; E = 1 ; N = $n ; M = $m ;
variables:
	double ListenerPosition(I, C) ;
		ListenerPosition:Type = "cartesian" ; ListenerPosition:Units = "metre" ;
	double ReceiverPosition(R, C, I) ;
		ReceiverPosition:Type = "cartesian" ; ReceiverPosition:Units = "metre" ;
	double SourcePosition(M, C) ;
		SourcePosition:Type = "spherical" ; SourcePosition:Units = "degree, degree, metre" ;
	double EmitterPosition(E, C, I) ;
		EmitterPosition:Type = "cartesian" ; EmitterPosition:Units = "metre" ;
	double ListenerUp(I, C) ;
	double ListenerView(I, C) ;
		ListenerView:Type = "cartesian" ; ListenerView:Units = "metre" ;
	double Data.IR(M, R, N) ;
	double Data.SamplingRate(I) ;
		Data.SamplingRate:Units = "hertz" ;
	double Data.Delay(I, R) ;
	:Conventions = "SOFA" ; :Version = "1.0" ; :SOFAConventions = "SimpleFreeFieldHRIR" ;
	:SOFAConventionsVersion = "1.0" ; :APIName = "fulgur test" ; :APIVersion = "1" ;
	:AuthorContact = "" ; :Comment = "" ; :DataType = "FIR" ; :License = "" ;
	:Organization = "" ; :RoomType = "free field" ; :DateCreated = "" ;
	:DateModified = "" ; :Title = "" ;
data:
	ListenerPosition = 0, 0, 0 ;
	EmitterPosition = 0, 0, 0 ;
	ListenerUp = 0, 0, 1 ;
	ListenerView = 1, 0, 0 ;
	Data.SamplingRate = $rate ;
CDL
        awk -v m="$m" -v r="$r" -v n="$n" -v last="$last" 'BEGIN {
            printf "\tReceiverPosition ="
            for (i = 0; i < r; i++) printf "%s 0, %s, 0", (i ? "," : ""), (i % 2 ? -0.09 : 0.09)
            printf " ;\n\tSourcePosition ="
            for (i = 0; i < m; i++) printf "%s %g, 0, 1", (i ? "," : ""), i * 360 / m
            printf " ;\n\tData.Delay ="
            for (i = 0; i < r; i++) printf "%s 0", (i ? "," : "")
            if (n != "UNLIMITED") {
                printf " ;\n\tData.IR ="
                total = m * r * n
                for (i = 0; i < total; i++) {
                    v = (i % n == 0) ? 0.5 : 0
                    if (last != "" && i == total - 1) v = last
                    printf "%s%s", (i ? ", " : " "), v
                    if (i % 16 == 15) printf "\n"
                }
            }
            printf " ;\n}\n"
        }'
    } | sed "$edit" >"$tmp/$name.cdl"
    ncgen -k nc4 -o "$tmp/$name.sofa" "$tmp/$name.cdl" || { echo "ncgen failed on $name.cdl"; exit 1; }
}
