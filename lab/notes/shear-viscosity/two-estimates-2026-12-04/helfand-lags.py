# η*(t) of the Helfand runs at chosen lags (in collision times 1/ω): run in the folder holding report-0.5/ and report-0.3/,
# written by: java -jar carom.jar simulate helfand-phiPHI.json --engine fast --observe viscosity --observe-every 0.5/ω --report report-PHI --summary summary-PHI.json
import csv,math,sys
def om(phi):
    chi=(1-7*phi/16)/(1-phi)**2; return 2*(phi/(math.pi/4))*chi*math.sqrt(math.pi)
for phi in (0.5,0.3):
    o=om(phi)
    rows=list(csv.DictReader(open(f'report-{phi}/viscosity.csv')))
    print('phi',phi,'rows',len(rows))
    for r in rows:
        t=float(r['lag'])*o
        if any(abs(math.log(t/x))<0.06 for x in (1,5,10,20,40,80,140,300,500,1000)):
            print(f"  t*omega {t:8.1f}  eta* {float(r['eta']):.4f} ± {float(r['error']):.4f}")
