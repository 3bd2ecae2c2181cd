# Mutant: Import never reports New (the paper, figure 3: Import:= New dropped).
s/result = ALB_NEW;/result = ALB_OLD;/
